// The file under each output of a run (history table, status file, log). Each write goes to the
// kernel at once with write(2), so a run that is killed keeps every line it finished, and the
// first failure (disk full, quota, I/O error) is kept with the file's name: the step driver stops
// the run on it and says which file failed, since a run must not end with part of its output
// silently missing.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace clinch {

class OutputFile {
 public:
  OutputFile() = default;
  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();

  // Creates (truncates) `path`. On failure returns false and sets `error` to
  // "cannot write 'PATH': REASON".
  bool open(const std::filesystem::path& path, std::string* error);

  // Writes `text` whole, retrying short writes. Returns false when it could not; the first such
  // failure is kept (error()). A later write is still tried, so that a run that stops can leave a
  // last line where space remains; it starts on a new line when a failed write left half a line.
  bool write(std::string_view text);

  // Forces what was written to the disk (fsync). Some file systems report a full disk or a lost
  // write only here (NFS, delayed allocation); such a failure is kept like a write's.
  bool sync();

  bool is_open() const { return fd_ >= 0; }
  bool failed() const { return !error_.empty(); }
  // "cannot write 'PATH': REASON" of the first failure; empty while none.
  const std::string& error() const { return error_; }

 private:
  bool write_all(std::string_view text);
  std::string describe(int code) const;  // "cannot write 'PATH': REASON"
  bool keep_error(int code);             // keeps the first failure; returns false
  void close();

  int fd_ = -1;
  std::string path_;
  std::string error_;
  bool at_line_start_ = true;
};

}  // namespace clinch
