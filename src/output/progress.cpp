#include "src/output/progress.hpp"

#include <unistd.h>

#include <iostream>
#include <string>

#include <fmt/format.h>

namespace clinch {

Progress Progress::for_stderr(bool quiet) {
  const bool terminal = isatty(STDERR_FILENO) == 1;
  return Progress(!quiet && terminal ? &std::cerr : nullptr);
}

void Progress::update(int step, int increment, double total_time, std::string_view step_name) {
  if (out_ == nullptr) return;
  const std::string name = step_name.empty() ? std::string() : fmt::format(" ({})", step_name);
  draw(fmt::format("step {}{}  increment {}  time {:.6g}", step, name, increment, total_time));
}

void Progress::show(std::string_view text) {
  if (out_ != nullptr) draw(text);
}

void Progress::clear() {
  if (out_ == nullptr || width_ == 0) return;
  *out_ << '\r' << std::string(width_, ' ') << '\r' << std::flush;
  width_ = 0;
}

void Progress::finish() {
  if (out_ == nullptr || width_ == 0) return;
  *out_ << '\n' << std::flush;
  width_ = 0;
}

void Progress::draw(std::string_view text) {
  // Pad with blanks over the rest of a longer previous line instead of relying on terminal
  // escape sequences.
  const std::size_t pad = width_ > text.size() ? width_ - text.size() : 0;
  *out_ << '\r' << text << std::string(pad, ' ') << std::flush;
  width_ = text.size() + pad;
}

}  // namespace clinch
