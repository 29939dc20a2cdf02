#include "src/behavior/plastic/uncoupled_return_mapping.hpp"

#include <algorithm>
#include <cmath>

#include "src/behavior/plastic/plastic_return_types.hpp"

namespace clinch {
namespace {

constexpr int kMaxIterations = 50;     // §6.3 step 2
constexpr double kTolerance = 1e-12;   // |r| ≤ 1e-12·F_y (§6.3 step 2)

struct Residual {
  double r = 0;      // r(Δλ)
  double slope = 0;  // dr/dΔλ = −(k + h + H_α)
  double hardening = 0;  // h + H_α
  double yield = 0;  // F_y(ū_n + Δλ)
};

}  // namespace

UncoupledReturn uncoupled_return(const UncoupledReturnInput& in) {
  UncoupledReturn out;
  const double k = in.stiffness;
  const double xi = in.trial_force - in.back_old;
  const double phi = std::abs(xi) - in.yield.at(in.equivalent_old).value;
  out.back = in.back_old;
  if (!(phi > 0)) return out;  // step 1: elastic (also NaN: the caller's checks catch it)
  out.plastic = true;
  const double s = xi > 0 ? 1.0 : -1.0;
  out.sign = s;
  const double abs_xi = std::abs(xi);

  // r(Δλ) = |ξ^tr| − k Δλ − s(α(Δλ) − α_n) − F_y(ū_n + Δλ); F_y and h come from the segment
  // that contains the iterate, which is how Newton steps across table breakpoints (§6.3).
  auto residual = [&](double dl) {
    Residual res;
    const YieldSample y = in.yield.at(in.equivalent_old + dl);
    double shift = 0, h_alpha = 0;
    if (in.kinematic != nullptr) {
      shift = s * (in.kinematic->back_force(in.back_old, s, dl) - in.back_old);
      h_alpha = in.kinematic->modulus(in.back_old, s, dl);
    }
    res.yield = y.value;
    res.r = abs_xi - k * dl - shift - y.value;
    res.hardening = y.slope + h_alpha;
    res.slope = -(k + res.hardening);
    return res;
  };

  // Bracket [lo, hi] with r(lo) > 0 ≥ r(hi). §6.3 suggests hi = |ξ^tr|/k; with Armstrong–
  // Frederick the back-force term can keep r positive there, so hi grows until it brackets.
  double lo = 0, hi = abs_xi / k;
  Residual at_hi = residual(hi);
  for (int grow = 0; at_hi.r > 0 && grow < 60; ++grow) {
    lo = hi;
    hi *= 2;
    at_hi = residual(hi);
  }
  if (at_hi.r > 0) {
    out.converged = false;
    return out;
  }

  // r is a difference of terms as large as |ξ^tr|: below a few ulps of |ξ^tr| it is round-off,
  // which 1e-12·F_y alone cannot allow for when F_y ≪ |ξ^tr| (plastic_return_types.hpp).
  const auto solved = [&](const Residual& at) {
    return std::abs(at.r) <= std::max(kTolerance * std::abs(at.yield), kReturnRoundOff * abs_xi);
  };
  double dl = lo;
  Residual res = residual(dl);
  out.converged = false;
  // The root at hi to round-off (F_y ≈ 0): Newton would land on hi, which the bracket excludes.
  if (solved(at_hi)) {
    dl = hi;
    res = at_hi;
    out.converged = true;
  }
  for (int it = 0; it < kMaxIterations && !out.converged; ++it) {
    if (solved(res) || hi - lo <= 1e-15 * hi) {
      out.converged = true;
      break;
    }
    if (res.r > 0) {
      lo = dl;
    } else {
      hi = dl;
    }
    // Newton, unless it leaves the bracket or r is not decreasing there: then bisection.
    double next = res.slope < 0 ? dl - res.r / res.slope : lo - 1.0;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    dl = next;
    res = residual(dl);
  }
  if (!out.converged) return out;
  out.multiplier = dl;
  if (in.kinematic != nullptr) out.back = in.kinematic->back_force(in.back_old, s, dl);
  out.tangent_denominator = k + res.hardening;
  return out;
}

}  // namespace clinch
