#include "parser/source_manager.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace clinch {

namespace {

// Opens a regular file for reading. Null with *error set to the system's reason on failure.
std::FILE* open_regular_file(const std::string& path, std::string* error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    if (error) *error = "Is a directory";
    return nullptr;
  }
  // Devices and pipes (/dev/zero, a FIFO) could block or never end: decks are regular files.
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
    if (error) *error = "not a regular file";
    return nullptr;
  }
  std::FILE* handle = std::fopen(path.c_str(), "rb");
  if (!handle && error) *error = std::strerror(errno);
  return handle;
}

// Reads a regular file that must still hold exactly `size` bytes (the size it had when it was
// parsed): one allocation, one read. False if it cannot be read or its size changed.
bool read_file_of_size(const std::string& path, std::size_t size, std::unique_ptr<char[]>& bytes) {
  std::FILE* handle = open_regular_file(path, nullptr);
  if (!handle) return false;
  bytes.reset(new char[std::max<std::size_t>(size, 1)]);
  const bool whole = std::fread(bytes.get(), 1, size, handle) == size &&
                     std::fgetc(handle) == EOF && !std::ferror(handle);
  std::fclose(handle);
  return whole;
}

// Line starts are 32-bit offsets: the largest deck that can be held in memory.
constexpr std::size_t kMaxInMemoryBytes = std::numeric_limits<std::uint32_t>::max();

// A deck path that is not simply a file on disk: the reader must take its bytes once, as they
// come, rather than open it again for each pass and for each line a diagnostic shows.
bool is_stream_path(const std::string& path) {
  if (path == "-" || path.starts_with("/dev/") || path.starts_with("/proc/")) return true;
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0 || S_ISDIR(status.st_mode)) {
    return false;  // load() gives the reason
  }
  return !S_ISREG(status.st_mode) || status.st_size == 0;
}

}  // namespace

std::optional<std::uint32_t> SourceManager::load_deck(const std::string& path, std::string* error) {
  if (!is_stream_path(path)) return load(path, {}, error);
  if (path == "-") return load_stream(STDIN_FILENO, "<stdin>", error);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    *error = std::strerror(errno);
    return std::nullopt;
  }
  std::optional<std::uint32_t> index = load_stream(fd, path, error);
  ::close(fd);
  return index;
}

std::optional<std::uint32_t> SourceManager::load_stream(int fd, std::string display_name,
                                                        std::string* error) {
  struct stat status {};
  if (::fstat(fd, &status) != 0) {
    *error = std::strerror(errno);
    return std::nullopt;
  }
  if (S_ISDIR(status.st_mode)) {
    *error = "Is a directory";
    return std::nullopt;
  }
  // A device other than a terminal may never end (/dev/zero, /dev/urandom).
  if (!S_ISREG(status.st_mode) && !S_ISFIFO(status.st_mode) && !S_ISSOCK(status.st_mode) &&
      !::isatty(fd)) {
    *error = "not a regular file, pipe or terminal";
    return std::nullopt;
  }
  std::string text;
  char chunk[64 * 1024];
  while (true) {
    const ssize_t got = ::read(fd, chunk, sizeof chunk);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      *error = std::strerror(errno);
      return std::nullopt;
    }
    if (text.size() + static_cast<std::size_t>(got) > kMaxInMemoryBytes) {
      *error = fmt::format("more than {} bytes", kMaxInMemoryBytes);
      return std::nullopt;
    }
    text.append(chunk, static_cast<std::size_t>(got));
  }
  // No path: relative includes resolve against the current directory (directory_of).
  const std::uint32_t index = add_buffer(std::move(display_name), std::move(text));
  files_[index].path.clear();
  return index;
}

std::optional<std::uint32_t> SourceManager::load(const std::string& path, SourceLoc included_from,
                                                 std::string* error) {
  std::FILE* handle = open_regular_file(path, error);
  if (!handle) return std::nullopt;
  std::fclose(handle);
  std::error_code size_error;
  const auto size = std::filesystem::file_size(path, size_error);
  const std::uint32_t index = add(path, path, nullptr, size_error ? 0 : size, included_from);
  files_[index].on_disk = true;
  files_[index].released = true;
  return index;
}

void SourceManager::release_texts() {
  for (SourceFile& file : files_) {
    if (!file.on_disk || file.released) continue;
    file.bytes.reset();
    file.text = {};
    file.line_starts = {};
    file.released = true;
  }
}

bool SourceManager::begin_layout(std::uint32_t index) {
  SourceFile& file = files_[index];
  if (file.layout_started) return false;
  file.layout_started = true;
  return true;
}

void SourceManager::record_keyword_line(std::uint32_t index, std::uint32_t line) {
  files_[index].keyword_lines.push_back(line);
}

void SourceManager::end_layout(std::uint32_t index, std::uint32_t line_count) {
  files_[index].line_count = line_count;
  files_[index].layout_known = true;
}

std::size_t SourceManager::lines_after_keyword(SourceLoc keyword) const {
  if (!keyword.valid() || keyword.file >= files_.size()) return 0;
  const SourceFile& file = files_[keyword.file];
  if (!file.layout_known || keyword.line > file.line_count) return 0;
  const auto next =
      std::upper_bound(file.keyword_lines.begin(), file.keyword_lines.end(), keyword.line);
  const std::uint32_t stop = next == file.keyword_lines.end() ? file.line_count + 1 : *next;
  return stop - keyword.line - 1;
}

void SourceManager::restore(SourceFile& file) const {
  if (!file.released) return;
  file.released = false;  // one attempt: a file that cannot be read back shows no lines
  std::unique_ptr<char[]> bytes;
  if (!read_file_of_size(file.path, file.size, bytes)) return;
  file.bytes = std::move(bytes);
  file.text = std::string_view(file.bytes.get(), file.size);
}

std::string_view SourceManager::text(std::uint32_t index) const {
  SourceFile& file = files_[index];
  restore(file);
  return file.text;
}

std::uint32_t SourceManager::add_buffer(std::string display_name, std::string text,
                                        SourceLoc included_from) {
  std::unique_ptr<char[]> bytes(new char[std::max<std::size_t>(text.size(), 1)]);
  std::memcpy(bytes.get(), text.data(), text.size());
  return add(display_name, display_name, std::move(bytes), text.size(), included_from);
}

std::uint32_t SourceManager::add(std::string path, std::string display_name,
                                 std::unique_ptr<char[]> bytes, std::size_t size,
                                 SourceLoc included_from) {
  SourceFile file;
  file.path = std::move(path);
  file.display_name = std::move(display_name);
  if (bytes) file.text = std::string_view(bytes.get(), size);
  file.bytes = std::move(bytes);
  file.size = size;
  file.included_from = included_from;
  files_.push_back(std::move(file));
  return static_cast<std::uint32_t>(files_.size() - 1);
}

void SourceManager::index_lines(SourceFile& file) const {
  if (!file.line_starts.empty()) return;
  file.line_starts.push_back(0);
  const std::string_view text = file.text;
  const char* begin = text.data();
  const char* end = begin + text.size();
  for (const char* p = begin; p < end;) {
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    if (!nl) break;
    p = static_cast<const char*>(nl) + 1;
    file.line_starts.push_back(static_cast<std::uint32_t>(p - begin));
  }
}

std::string_view SourceManager::line_text(SourceLoc loc) const {
  if (!loc.valid() || loc.file >= files_.size() || loc.line == 0) return {};
  SourceFile& file = files_[loc.file];
  restore(file);
  if (file.text.size() != file.size) return {};  // released and not readable as it was
  index_lines(file);
  if (loc.line > file.line_starts.size()) return {};
  std::size_t begin = file.line_starts[loc.line - 1];
  std::size_t end = file.text.find('\n', begin);
  if (end == std::string_view::npos) end = file.text.size();
  if (end > begin && file.text[end - 1] == '\r') --end;
  return file.text.substr(begin, end - begin);
}

std::string SourceManager::format(SourceLoc loc) const {
  if (!loc.valid() || loc.file >= files_.size()) return "<unknown>";
  return fmt::format("{}:{}:{}", files_[loc.file].display_name, loc.line, loc.column);
}

std::string SourceManager::directory_of(std::uint32_t index) const {
  std::filesystem::path path(files_[index].path);
  return path.parent_path().string();
}

}  // namespace clinch
