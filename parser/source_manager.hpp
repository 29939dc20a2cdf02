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

#include "base/source_location.hpp"

namespace clinch {

struct SourceFile {
  std::string path;          // as opened (resolved against the including file's directory)
  std::string display_name;  // as shown in diagnostics
  // Whole contents, in `bytes`: always for in-memory buffers; for a file on disk only once a
  // diagnostic has asked for one of its lines (the reader streams it, lexer.hpp LineScanner).
  std::string_view text;
  // Owns the contents. Not a std::string: its resize() would zero the buffer before the read
  // overwrites it, a pass over fresh memory that costs as much as the read itself (docs/
  // performance.md).
  std::unique_ptr<char[]> bytes;
  std::vector<std::uint32_t> line_starts;  // byte offset of each line (filled lazily)
  SourceLoc included_from;  // the *INCLUDE or INPUT= value that opened it; invalid for the deck
  // On disk (not an in-memory buffer): its contents are not held, and are read when a
  // diagnostic shows one of its lines.
  bool on_disk = false;
  bool released = false;  // on disk and contents not in memory
  std::size_t size = 0;   // when it was opened: a file of another size is not the one parsed
  // Where its keyword lines are, learnt by the reader's first pass, so that a block can size its
  // storage before its data lines are read (lines_after_keyword).
  std::vector<std::uint32_t> keyword_lines;
  std::uint32_t line_count = 0;
  bool layout_started = false, layout_known = false;
};

class SourceManager {
 public:
  // Registers a file on disk after checking that it is a regular file that can be opened; its
  // contents are not read. On failure returns nullopt and sets *error to the system's reason.
  std::optional<std::uint32_t> load(const std::string& path, SourceLoc included_from,
                                    std::string* error);
  // Registers the deck named on the command line. A regular file with a size is registered like
  // any other file (load). Anything else cannot be read twice, as the reader and its diagnostics
  // do, and is read whole into memory now: "-" (standard input, shown as "<stdin>"), a pipe, a
  // socket, a terminal, any path under /dev/ or /proc/ (/dev/stdin, /proc/self/fd/N) and a
  // pseudo-file whose size stat does not tell. Such a deck resolves relative *INCLUDE and INPUT=
  // paths against the current directory. Other devices (/dev/zero never ends) are refused. On
  // failure, open or read, returns nullopt and sets *error to the system's reason.
  std::optional<std::uint32_t> load_deck(const std::string& path, std::string* error);
  // Adds in-memory text (tests, fuzzers).
  std::uint32_t add_buffer(std::string display_name, std::string text,
                           SourceLoc included_from = {});

  const SourceFile& file(std::uint32_t index) const { return files_[index]; }
  // The whole contents of one file, read again from disk if they were released ("" when the
  // file can no longer be read or its size changed since it was parsed).
  std::string_view text(std::uint32_t index) const;
  // Frees the contents of every file on disk that a diagnostic read back (text, line_text).
  void release_texts();
  // The layout of a file's lines, recorded once by the reader's first pass: begin_layout is true
  // for the scan that records it (the first), which then calls record_keyword_line for each
  // keyword line and end_layout with the number of lines.
  bool begin_layout(std::uint32_t index);
  void record_keyword_line(std::uint32_t index, std::uint32_t line);
  void end_layout(std::uint32_t index, std::uint32_t line_count);
  // Lines after the keyword line at `keyword` up to the next keyword line or the end of its file
  // (comment lines included): a bound on the data lines of its block; 0 when not recorded.
  std::size_t lines_after_keyword(SourceLoc keyword) const;
  std::uint32_t file_count() const { return static_cast<std::uint32_t>(files_.size()); }
  // The first read error of a file on disk, part-way through it (check_read_whole): an I/O
  // error (exit 3), not a fault of the deck. "" when every read succeeded.
  void note_read_error(std::string message) {
    if (read_error_.empty()) read_error_ = std::move(message);
  }
  const std::string& read_error() const { return read_error_; }
  // The text of one physical line without its line end ("" when out of range).
  std::string_view line_text(SourceLoc loc) const;
  // "deck.inp:12:3"
  std::string format(SourceLoc loc) const;
  // Directory part of a file's path, for resolving relative includes.
  std::string directory_of(std::uint32_t index) const;

 private:
  std::uint32_t add(std::string path, std::string display_name, std::unique_ptr<char[]> bytes,
                    std::size_t size, SourceLoc included_from);
  // Reads `fd` to its end into an in-memory file shown as `display_name` (load_deck).
  std::optional<std::uint32_t> load_stream(int fd, std::string display_name, std::string* error);
  void index_lines(SourceFile& file) const;
  // Reads a released file back (text() and line_text()).
  void restore(SourceFile& file) const;
  mutable std::vector<SourceFile> files_;
  std::string read_error_;
};

}  // namespace clinch
