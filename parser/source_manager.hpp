// The file table: every deck, *INCLUDE and INPUT= file that was opened, its bytes, where each line
// starts, and the line that included it. Locations are (file, line, column); this class turns them
// into a display name and the text of the line for diagnostics.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/source_location.hpp"

namespace clinch {

struct SourceFile {
  std::string path;          // as opened (resolved against the including file's directory)
  std::string display_name;  // as shown in diagnostics
  std::string_view text;     // whole contents, in `bytes`
  // Owns the contents. Not a std::string: its resize() would zero the buffer before the read
  // overwrites it, a pass over fresh memory that costs as much as the read itself (docs/
  // performance.md).
  std::unique_ptr<char[]> bytes;
  std::vector<std::uint32_t> line_starts;  // byte offset of each line (filled lazily)
  SourceLoc included_from;   // the *INCLUDE or INPUT= value that opened it; invalid for the deck
};

class SourceManager {
 public:
  // Reads a file. On failure returns nullopt and sets *error to the system's reason.
  std::optional<std::uint32_t> load(const std::string& path, SourceLoc included_from,
                                    std::string* error);
  // Adds in-memory text (tests, fuzzers).
  std::uint32_t add_buffer(std::string display_name, std::string text,
                           SourceLoc included_from = {});

  const SourceFile& file(std::uint32_t index) const { return files_[index]; }
  std::uint32_t file_count() const { return static_cast<std::uint32_t>(files_.size()); }
  // The text of one physical line without its line end ("" when out of range).
  std::string_view line_text(SourceLoc loc) const;
  // "deck.inp:12:3"
  std::string format(SourceLoc loc) const;
  // Directory part of a file's path, for resolving relative includes.
  std::string directory_of(std::uint32_t index) const;

 private:
  std::uint32_t add(std::string path, std::string display_name, std::unique_ptr<char[]> bytes,
                    std::size_t size, SourceLoc included_from);
  void index_lines(SourceFile& file) const;
  mutable std::vector<SourceFile> files_;
};

}  // namespace clinch
