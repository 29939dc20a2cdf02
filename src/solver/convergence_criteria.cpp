#include "src/solver/convergence_criteria.hpp"

#include <algorithm>

namespace clinch {

void ConvergenceCriteria::start_step(const Controls& controls) { controls_ = controls; }

double ConvergenceCriteria::time_average(int f) const {
  // Before any force has appeared, q̄ is q̄₀ (§16 field 3).
  return flux_count_[f] > 0 ? flux_sum_[f] / flux_count_[f] : field(f).initial_flux;
}

// The field carries force in this iteration: its flux is above round-off beside the other field
// (IterationNorms::force_resolution) and above ε times q̄ of the increments so far (§16 field 6).
// A flux at most ε·q̄ is zero: it takes the zero-force test and does not join q̄, so that a
// model without forces (a mechanism turned by a connector motion alone) does not take the
// round-off of its forces, 1e-30, for its q̄ and then fail Rₙ on a residual of the same round-off.
bool ConvergenceCriteria::carries_force(const IterationNorms& norms, int f) const {
  const double flux = norms.flux[f];
  if (!(flux > 0 && flux > norms.force_resolution[f])) return false;
  const FieldControls& c = field(f);
  return flux > c.zero_flux * (c.user_flux ? *c.user_flux : time_average(f));
}

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
  if (!carries_force(norms, f)) return time_average(f);
  return (flux_sum_[f] + norms.flux[f]) / (flux_count_[f] + 1);
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
