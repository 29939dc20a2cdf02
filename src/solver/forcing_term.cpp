#include "src/solver/forcing_term.hpp"

#include <algorithm>

namespace clinch {

double ForcingTerm::next(int k, double residual_norm) {
  double eta = kFirst;
  if (k > 0 && previous_norm_ > 0) {
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
