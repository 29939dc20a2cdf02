#include "src/solver/forcing_term.hpp"

#include <algorithm>
#include <cmath>

namespace clinch {

double ForcingTerm::next(int k, double residual_norm) {
  double eta = kFirst;
  // A norm that is not finite (an overflowing residual: Newton stops on it) has no ratio to go
  // by; the term then stays at kFirst rather than become NaN.
  const bool ratio_known = k > 0 && previous_norm_ > 0 && std::isfinite(previous_norm_) &&
                           std::isfinite(residual_norm);
  if (ratio_known) {
    const double ratio = residual_norm / previous_norm_;
    eta = kGamma * ratio * ratio;
    // Eisenstat–Walker's safeguard: a sudden drop of η after slow progress over-solves.
    const double carried = kGamma * previous_eta_ * previous_eta_;
    if (carried > 0.1) eta = std::max(eta, carried);
  }
  eta = std::clamp(eta, kSmallest, kLargest);
  previous_norm_ = residual_norm;
  previous_eta_ = eta;
  return eta;
}

}  // namespace clinch
