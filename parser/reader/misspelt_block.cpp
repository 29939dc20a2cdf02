#include "parser/reader/misspelt_block.hpp"

#include <fmt/format.h>

namespace clinch {

bool MisspeltBlock::changes_structure(const KeywordSpec& meant) {
  const std::string_view n = meant.name;
  return n == "CONNECTOR BEHAVIOR" || n == "STEP" || n == "END STEP" || n == "END PART" ||
         n == "END ASSEMBLY" || n == "END INSTANCE";
}

void MisspeltBlock::begin(std::size_t error_index, const KeywordSpec& meant,
                          const KeywordLine& line) {
  const std::string_view n = meant.name;
  open_ = n == "CONNECTOR BEHAVIOR" || n == "STEP";  // the blocks with contents to count
  if (!open_) return;
  behavior_ = n == "CONNECTOR BEHAVIOR";
  error_index_ = error_index;
  loc_ = line.loc;
  meant_ = meant.name;
  name_.clear();
  for (const KeywordParam& p : line.params) {
    if (p.name == "NAME" && p.has_value && !p.value.text.empty()) name_ = p.value.text;
  }
  blocks_ = 0;
  first_line_ = last_line_ = 0;
}

void MisspeltBlock::keyword(const KeywordLine& line, bool inside, DiagnosticSink& sink) {
  if (!open_) return;
  if (!inside) {
    finish(sink);
    return;
  }
  if (blocks_++ == 0) first_line_ = line.loc.line;
  last_line_ = line.loc.line;
}

void MisspeltBlock::finish(DiagnosticSink& sink) {
  if (!open_) return;
  open_ = false;
  const std::string what = behavior_ ? "sub-option block" : "history block";
  const std::string lines = blocks_ == 0              ? std::string()
                            : first_line_ == last_line_ ? fmt::format(" (line {})", first_line_)
                                                        : fmt::format(" (lines {}-{})",
                                                                      first_line_, last_line_);
  const std::string named = name_.empty() ? std::string() : fmt::format(" '{}'", name_);
  std::string message = fmt::format(
      "read as *{}{} so that what follows is checked where it stands: the {} {}{} after it{} "
      "{} checked but {}",
      meant_, named, blocks_, what, blocks_ == 1 ? "" : "s", lines, blocks_ == 1 ? "is" : "are",
      behavior_ ? (blocks_ == 1 ? "defines nothing" : "define nothing") : "not run");
  if (behavior_ && !name_.empty()) {
    message += fmt::format(", and references to '{}' are not reported", name_);
  }
  sink.add_note(error_index_, {loc_, std::move(message)});
}

}  // namespace clinch
