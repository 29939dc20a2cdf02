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
  SourceLoc included_from;  // the *INCLUDE or INPUT= value that opened it; invalid for the deck
  // Read from disk (not an in-memory buffer), so its contents can be released after parsing and
  // read again when a diagnostic shows one of its lines.
  bool on_disk = false;
  bool released = false;
  std::size_t size = 0;  // of the contents that were parsed
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
  // The whole contents of one file, read again from disk if they were released ("" when the
  // file can no longer be read or its size changed since it was parsed).
  std::string_view text(std::uint32_t index) const;
  // Frees the contents of every file read from disk. Parsing is over once the model is built;
  // only diagnostics look at the text again, and they read it back on demand (text, line_text).
  // A deck as large as the memory it becomes is then no longer held through validation and the
  // analysis.
  void release_texts();
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
  // Reads a released file back (text() and line_text()).
  void restore(SourceFile& file) const;
  mutable std::vector<SourceFile> files_;
};

}  // namespace clinch
