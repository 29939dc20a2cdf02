// Pivot tests and failure messages shared by the factorization backends, so that CHOLMOD,
// UMFPACK and the dense reference agree on what a singular system is and how it is reported
// (connection-types.md §1.1: the run stops on the singular pivot and names it).
#pragma once

#include <string>

#include "src/linalg/linear_solver.hpp"

namespace clinch {

// A pivot is negligible when cancellation has removed all but about 3 of its 16 significant
// digits: |pivot| <= kSingularPivotTolerance * reference, where the reference is the diagonal of
// the matrix (Cholesky) or the largest entry of the pivot column of the row-scaled matrix (LU),
// both invariant to the units of the unknowns. Exactly singular systems (a rigid-body mode, an
// unrestrained dof) leave pivots of a few machine epsilons; stiffness contrasts up to 1e12 stay
// above it.
inline constexpr double kSingularPivotTolerance = 1e-13;

bool negligible_pivot(double pivot, double reference);

// Status of a Cholesky factorization that met the non-positive pivot `schur` at an equation whose
// diagonal entry is `diagonal`. A negligible pivot on a positive diagonal, or a line of zeros,
// makes the system singular; otherwise the matrix is indefinite (a zero diagonal with a nonzero
// off-diagonal entry has a negative 2×2 minor).
LinearStatus classify_cholesky_failure(double schur, double diagonal, bool zero_line);

// "singular system: zero pivot at equation 12" and the like; `backend` names the solver.
std::string pivot_message(LinearStatus status, int pivot, const char* backend);

// "non-finite entry (nan) at row 3, column 7 (cholmod)" for the entry at `position` of `k`.
std::string non_finite_message(const SparseMatrix& k, int position, const char* backend);

// Writes `text` to `message` when the caller asked for messages.
void set_message(std::string* message, std::string text);

}  // namespace clinch
