#include "src/linalg/pivot_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace clinch {

bool negligible_pivot(double pivot, double reference) {
  return std::abs(pivot) <= kSingularPivotTolerance * std::abs(reference);
}

LinearStatus classify_cholesky_failure(double schur, double diagonal, bool zero_line) {
  if (zero_line) return LinearStatus::Singular;
  if (diagonal > 0.0 && negligible_pivot(schur, diagonal)) return LinearStatus::Singular;
  return LinearStatus::NotPositiveDefinite;
}

std::string pivot_message(LinearStatus status, int pivot, const char* backend) {
  const std::string where =
      pivot >= 0 ? fmt::format("equation {}", pivot) : std::string("an unknown equation");
  switch (status) {
    case LinearStatus::Singular:
      return fmt::format("singular system: zero pivot at {} ({})", where, backend);
    case LinearStatus::NotPositiveDefinite:
      return fmt::format("matrix not positive definite: negative pivot at {} ({})", where, backend);
    case LinearStatus::Ok:
    case LinearStatus::Failure:
      break;
  }
  return fmt::format("factorization failed at {} ({})", where, backend);
}

std::string non_finite_message(const SparseMatrix& k, int position, const char* backend) {
  const auto column =
      std::upper_bound(k.col_ptr.begin(), k.col_ptr.end(), position) - k.col_ptr.begin() - 1;
  return fmt::format("non-finite entry ({}) at row {}, column {} ({})", k.values[position],
                     k.row_idx[position], column, backend);
}

void set_message(std::string* message, std::string text) {
  if (message != nullptr) *message = std::move(text);
}

}  // namespace clinch
