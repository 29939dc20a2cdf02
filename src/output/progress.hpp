// Progress display for `clinch run` and `clinch study` (cli-contract.md): one stderr line
// rewritten with '\r' (a run's step, increment and time; a study's settings), only when stderr is
// a terminal and the command is not quiet.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string_view>

namespace clinch {

class Progress {
 public:
  // Shows progress on std::cerr when stderr is a terminal and `quiet` is false.
  static Progress for_stderr(bool quiet);

  // Shows progress on `out`; a null stream shows nothing.
  explicit Progress(std::ostream* out) : out_(out) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  Progress(Progress&& other) noexcept : out_(other.out_), width_(other.width_) {
    other.out_ = nullptr;
  }
  Progress& operator=(Progress&&) = delete;
  ~Progress() { finish(); }

  bool enabled() const { return out_ != nullptr; }

  // `step_name`: the step's NAME= (or Step-<n>), shown after its number when not empty.
  void update(int step, int increment, double total_time, std::string_view step_name = {});
  // Shows a free-form progress line.
  void show(std::string_view text);
  // Erases the progress line, e.g. before a message is printed on the same stream; the next
  // update() draws it again.
  void clear();
  // Ends the progress line with a newline so that later output starts on a fresh line.
  void finish();

 private:
  void draw(std::string_view text);

  std::ostream* out_;
  std::size_t width_ = 0;  // length of the line on screen, 0 when none is shown
};

}  // namespace clinch
