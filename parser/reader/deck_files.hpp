// The files of one deck: the deck itself, the files *INCLUDE splices in (input-syntax.md §5.1) and
// those INPUT= reads (§5.2). Each file is loaded once, and a relative name is resolved against
// the directory of the file that names it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>

#include "base/diagnostic.hpp"
#include "base/source_location.hpp"
#include "parser/lexer.hpp"
#include "parser/reader/line_stream.hpp"
#include "parser/source_manager.hpp"

namespace clinch {

// How many files may be open at once through nested *INCLUDE (a longer chain is refused).
inline constexpr std::size_t kMaxIncludeDepth = 32;

class DeckFiles {
 public:
  DeckFiles(SourceManager& sources, DiagnosticSink& sink) : sources_(sources), sink_(sink) {}

  // The deck itself, already loaded: an *INCLUDE of it shares its entry.
  void add_main(std::uint32_t main_file);

  // The path of `name` as written in from_file.
  std::string resolve(std::uint32_t from_file, const std::string& name) const;

  // Each file is registered once; both passes (and repeated includes) share its entry.
  std::optional<std::uint32_t> load_once(const std::string& path, SourceLoc at, std::string* error);
  // load_once without the reason of a failure: the pre-pass passes over a file it cannot open,
  // and the second pass reports it.
  std::optional<std::uint32_t> try_load(const std::string& path, SourceLoc at);

  // *INCLUDE, INPUT=file: checks the line, refuses cycles and too deep nesting, and pushes the
  // file onto the stream.
  void include(const KeywordLine& line, LineStream& stream);

 private:
  SourceManager& sources_;
  DiagnosticSink& sink_;
  std::unordered_map<std::string, std::uint32_t> loaded_;
};

}  // namespace clinch
