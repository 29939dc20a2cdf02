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
    *error = fmt::format("cannot write '{}': {}", path_, std::strerror(errno));
    return false;
  }
  return true;
}

bool OutputFile::write(std::string_view text) {
  if (fd_ < 0) return false;
  if (!at_line_start_ && !write_all("\n")) return false;
  return write_all(text);
}

bool OutputFile::write_all(std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd_, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int code = n < 0 ? errno : ENOSPC;  // a write of 0 bytes makes no progress
      if (error_.empty()) error_ = fmt::format("cannot write '{}': {}", path_, std::strerror(code));
      return false;
    }
    at_line_start_ = text[static_cast<std::size_t>(n) - 1] == '\n';
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace clinch
