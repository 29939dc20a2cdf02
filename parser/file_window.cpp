#include "parser/file_window.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace clinch {

FileWindow::FileWindow(const std::string& path, std::size_t capacity)
    : capacity_(std::max<std::size_t>(capacity, 2)) {
  handle_ = std::fopen(path.c_str(), "rb");
  if (!handle_) {
    error_ = std::strerror(errno);
    return;
  }
  allocate();
}

FileWindow::FileWindow(std::FILE* handle, std::size_t capacity)
    : handle_(handle), capacity_(std::max<std::size_t>(capacity, 2)) {
  if (handle_) allocate();
}

void FileWindow::allocate() {
  std::setvbuf(handle_, nullptr, _IONBF, 0);  // reads go straight into the window
  buffer_.reset(new char[capacity_]);
}

FileWindow::~FileWindow() {
  if (handle_) std::fclose(handle_);
}

bool FileWindow::refill(std::size_t keep) {
  if (!handle_ || std::feof(handle_) || read_failed_) return false;
  keep = std::min(keep, filled_);
  const std::size_t kept = filled_ - keep;
  if (kept > capacity_ / 2) {
    const std::size_t grown_capacity = 2 * capacity_;
    std::unique_ptr<char[]> grown(new char[grown_capacity]);
    std::memcpy(grown.get(), buffer_.get() + keep, kept);
    buffer_ = std::move(grown);
    capacity_ = grown_capacity;
  } else if (kept > 0 && keep > 0) {
    std::memmove(buffer_.get(), buffer_.get() + keep, kept);
  }
  filled_ = kept;
  errno = 0;
  const std::size_t got = std::fread(buffer_.get() + filled_, 1, capacity_ - filled_, handle_);
  if (std::ferror(handle_)) {
    read_failed_ = true;
    error_ = errno != 0 ? std::strerror(errno) : "read error";
  }
  filled_ += got;
  bytes_read_ += got;
  return got > 0;
}

}  // namespace clinch
