#include "src/output/run_log.hpp"

#include <ostream>

#include <fmt/format.h>

namespace clinch {

bool RunLog::open(const std::filesystem::path& path, std::string* error) {
  return file_.open(path, error);
}

void RunLog::info(std::string_view text) { emit(text, info_echo_); }

void RunLog::warning(std::string_view text) { emit(text, warning_echo_); }

void RunLog::error(std::string_view text) { emit(text, warning_echo_); }

void RunLog::iteration(const IterationRecord& r) {
  // Norms in scientific notation with 6 digits: enough to read the convergence rate, and every
  // line keeps the same width.
  auto at = [](const std::string& where) {
    return where.empty() ? std::string() : fmt::format(" at {}", where);
  };
  emit(fmt::format("step {} increment {} attempt {} iteration {}: residual {:.6e} (largest "
                   "{:.6e}{}), correction {:.6e} (largest {:.6e}{}), constraint violation {:.6e}",
                   r.step, r.increment, r.attempt, r.iteration, r.residual_norm, r.largest_residual,
                   at(r.largest_residual_at), r.correction_norm, r.largest_correction,
                   at(r.largest_correction_at), r.constraint_violation),
       nullptr);
}

void RunLog::emit(std::string_view text, std::ostream* echo) {
  const bool needs_newline = text.empty() || text.back() != '\n';
  if (file_.is_open()) {
    line_.assign(text);
    if (needs_newline) line_ += '\n';
    file_.write(line_);
  }
  if (echo != nullptr) {
    *echo << text;
    if (needs_newline) *echo << '\n';
    echo->flush();
  }
}

}  // namespace clinch
