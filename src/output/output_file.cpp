#include "src/output/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace clinch {

OutputFile::OutputFile(OutputFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      path_(std::move(other.path_)),
      error_(std::move(other.error_)),
      at_line_start_(other.at_line_start_) {}

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    path_ = std::move(other.path_);
    error_ = std::move(other.error_);
    at_line_start_ = other.at_line_start_;
  }
  return *this;
}

OutputFile::~OutputFile() { close(); }

std::string OutputFile::describe(int code) const {
  return fmt::format("cannot write '{}': {}", path_, std::strerror(code));
}

bool OutputFile::keep_error(int code) {
  if (error_.empty()) error_ = describe(code);
  return false;
}

void OutputFile::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

bool OutputFile::open(const std::filesystem::path& path, std::string* error) {
  close();
  path_ = path.string();
  error_.clear();
  at_line_start_ = true;
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    *error = describe(errno);
    return false;
  }
  return true;
}

bool OutputFile::write(std::string_view text) {
  if (fd_ < 0) return false;
  if (!at_line_start_ && !write_all("\n")) return false;
  return write_all(text);
}

bool OutputFile::sync() {
  if (fd_ < 0) return false;
  if (::fsync(fd_) == 0) return true;
  // fsync fails with EINVAL on special files, which hold nothing to force.
  if (errno == EINVAL || errno == EROFS) return true;
  return keep_error(errno);
}

bool OutputFile::write_all(std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd_, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      return keep_error(n < 0 ? errno : ENOSPC);  // a write of 0 bytes makes no progress
    }
    at_line_start_ = text[static_cast<std::size_t>(n) - 1] == '\n';
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace clinch
