#include "src/solver/convergence_criteria.hpp"

#include <algorithm>

namespace clinch {

void ConvergenceCriteria::start_step(const Controls& controls) { controls_ = controls; }

namespace {

// The field has a flux above round-off (IterationNorms::force_resolution).
bool carries_force(const IterationNorms& norms, int f) {
  return norms.flux[f] > 0 && norms.flux[f] > norms.force_resolution[f];
}

}  // namespace

void ConvergenceCriteria::accept_increment(const IterationNorms& norms) {
  for (int f = 0; f < 2; ++f) {
    if (!carries_force(norms, f)) continue;
    flux_sum_[f] += norms.flux[f];
    ++flux_count_[f];
  }
}

double ConvergenceCriteria::average_flux(const IterationNorms& norms, int f) const {
  const FieldControls& c = field(f);
  if (c.user_flux) return *c.user_flux;
  double sum = flux_sum_[f];
  int count = flux_count_[f];
  if (carries_force(norms, f)) {
    sum += norms.flux[f];
    ++count;
  }
  // Before any force has appeared, q̄ is q̄₀ (§16 field 3).
  return count > 0 ? sum / count : c.initial_flux;
}

bool ConvergenceCriteria::converged(const IterationNorms& norms, int iteration) const {
  if (norms.constraint_violation > 1.0) return false;
  for (int f = 0; f < 2; ++f) {
    const FieldControls& c = field(f);
    const double q = average_flux(norms, f);
    const double r = norms.largest_residual[f];
    // A field that is linear in the increment converges after one iteration (ε_l). Before any
    // iteration only that test can pass: an extrapolated start is not accepted on the looser
    // Rₙ test, where its small error would be carried into every later increment.
    if (r <= c.linear_residual * q) continue;
    if (iteration == 0) return false;
    const double du = std::max(norms.largest_increment[f], 1e-300);
    // A correction at round-off passes whatever the increment (a field that does not move).
    const double dc = norms.largest_correction[f];
    const bool round_off = dc <= norms.resolution[f];
    // Zero-force field: only the correction test, with C_ε (§16 fields 6–7).
    if (norms.flux[f] <= c.zero_flux * q || !carries_force(norms, f)) {
      if (dc > c.zero_flux_correction * du && !round_off) return false;
      continue;
    }
    const double tolerance = iteration > controls_.time.ip ? c.alternate_residual : c.residual;
    if (r > tolerance * q) return false;
    if (dc > c.correction * du && !round_off) return false;
  }
  return true;
}

}  // namespace clinch
