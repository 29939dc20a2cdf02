// A file read front to back through one reused buffer. The deck reader scans a file line by line
// and never looks back, so it needs only the current line in memory: a deck of 10⁶ connectors
// (84 MB) is read through a quarter-megabyte window that stays in cache, instead of becoming a
// fresh 84 MB buffer that the kernel must zero and fill (docs/performance.md, "The deck is
// streamed, never held whole").
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace clinch {

class FileWindow {
 public:
  static constexpr std::size_t kDefaultCapacity = 256 * 1024;

  // Opens `path` for reading; ok() is false (and error() says why) when it cannot be opened.
  explicit FileWindow(const std::string& path, std::size_t capacity = kDefaultCapacity);
  // Reads an open stream, which it closes (tests inject one whose reads fail, fopencookie).
  explicit FileWindow(std::FILE* handle, std::size_t capacity = kDefaultCapacity);
  ~FileWindow();
  FileWindow(const FileWindow&) = delete;
  FileWindow& operator=(const FileWindow&) = delete;

  bool ok() const { return handle_ != nullptr; }
  // Why the file could not be opened, or why a read failed (the system's reason).
  const std::string& error() const { return error_; }
  // The bytes in the window: what the last refill kept, then what it read.
  std::string_view contents() const { return {buffer_.get(), filled_}; }
  // Moves contents()[keep..] to the front and reads after it; the buffer doubles when the kept
  // bytes fill more than half of it (a line longer than the window). False when nothing more
  // could be read: the end of the file, or a read error (read_failed()).
  bool refill(std::size_t keep);
  bool read_failed() const { return read_failed_; }
  // Bytes read from the file so far.
  std::uint64_t bytes_read() const { return bytes_read_; }

 private:
  void allocate();

  std::FILE* handle_ = nullptr;
  std::string error_;
  std::unique_ptr<char[]> buffer_;
  std::size_t capacity_ = 0;
  std::size_t filled_ = 0;
  std::uint64_t bytes_read_ = 0;
  bool read_failed_ = false;
};

}  // namespace clinch
