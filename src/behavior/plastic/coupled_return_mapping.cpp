#include "src/behavior/plastic/coupled_return_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "src/behavior/behavior.hpp"
#include "base/small_cholesky.hpp"

namespace clinch {
namespace {

constexpr int kMaxNewtonIterations = 30;         // §6.4 step 2
constexpr int kMaxHalvings = 10;                 // §6.4 step 2
constexpr int kMaxCuttingPlaneIterations = 200;  // §6.4 step 3
constexpr double kTolerance = 1e-12;             // §6.4 steps 2 and 3
// Armijo constant of the backtracking line search: any decrease proportional to the step is
// enough; the merit only guards Newton against overshooting a kink of the potential.
constexpr double kArmijo = 1e-4;
// Where a released kink group restarts, as a fraction of its trial force (closest_point_return).
constexpr double kReleaseOffset = 1e-6;

// One iterate of the closest-point Newton: (F, Δλ), P and its derivatives at F, F_y and h at
// ū_n + Δλ, the residuals of §6.4 and the merit. Components of `held` (collapsed kink groups)
// are fixed at zero: their rows of R_F are dropped from the residual.
struct Iterate {
  Vector6 force;
  double multiplier = 0;
  PotentialValue potential;
  YieldSample yield;
  Vector6 residual_force;  // R_F = K⁻¹(F − F^tr) + Δλ n
  double residual_yield = 0;  // R_λ = P(F) − F_y(ū_n + Δλ)
  double merit = 0;
};

struct Scales {
  double motion;  // ‖K⁻¹ F^tr‖: the stopping scale of R_F (§6.4 step 2)
  double force;   // F_y(ū_n), at least `floor`
  double floor;   // the round-off of R_λ: kReturnRoundOff·P(F^tr)
};

void evaluate(const ElasticSpace& space, const ConnectorPotential& potential,
              YieldFunction yield, const Vector6& trial, double equivalent_old,
              const Scales& scales, bool hessian, ComponentMask held, Iterate& it) {
  potential.evaluate(it.force, it.potential, hessian);
  it.yield = yield.at(equivalent_old + it.multiplier);
  it.residual_force.noalias() = space.compliance * (it.force - trial);
  it.residual_force += it.multiplier * it.potential.gradient;
  if (held) it.residual_force = it.residual_force.cwiseProduct(mask_vector(~held));
  it.residual_yield = it.potential.value - it.yield.value;
  // §6.4 asks for ‖R_F‖² + (R_λ/F_y)²; R_F is divided by its own stopping scale too, so that the
  // two terms are dimensionless and weighted as the stopping test weights them.
  const double rf = it.residual_force.norm() / scales.motion;
  const double rl = it.residual_yield / scales.force;
  it.merit = rf * rf + rl * rl;
}

bool converged(const Iterate& it, const Scales& scales) {
  return it.residual_force.norm() <= kTolerance * scales.motion &&
         std::abs(it.residual_yield) <= std::max(kTolerance * it.yield.value, scales.floor);
}

// M = K⁻¹ + Δλ N2 with the rows and columns of `held` replaced by the identity, so that a solve
// leaves those components where they are.
Matrix6 reduced_jacobian(const ElasticSpace& space, const Matrix6& hessian, double multiplier,
                         ComponentMask held) {
  Matrix6 m = space.compliance;
  if (multiplier > 0) m += multiplier * hessian;
  for (int i = 0; i < 6; ++i) {
    if (!((held >> i) & 1u)) continue;
    m.row(i).setZero();
    m.col(i).setZero();
    m(i, i) = 1.0;
  }
  return m;
}

// A kink group crossed by the step from `from` to `to`: a NORM group whose resultant turns by
// more than 90°, or a MACAULEY component that leaves the active side; both overshoot the kink at
// zero, where the exact return may have to stop (derived-components-and-potentials.md §1.4).
bool crosses(const KinkGroup& g, const Vector6& from, const Vector6& to) {
  double before = 0, across = 0;
  for (int i = 0; i < 6; ++i) {
    if (!((g.components >> i) & 1u)) continue;
    if (g.macauley) {
      before = g.coefficient[i] * from[i];
      across = g.coefficient[i] * to[i];
    } else {
      before += from[i] * from[i];
      across += from[i] * to[i];
    }
  }
  return before > 0 && across <= 0;
}

// With group `g` held at zero, the dropped rows of the flow rule, K⁻¹(F − F^tr) + Δλ ζ̃ = 0, need
// ζ̃ in the subdifferential n_i·(C∘ζ), ‖ζ‖ ≤ 1 (NORM) or ζ ∈ [0, 1] (MACAULEY). Returns by how
// much ζ leaves that set (0 when the hold is admissible): a positive value means the exact
// return leaves the kink, and the group must be released.
double hold_violation(const KinkGroup& g, const ElasticSpace& space, const Vector6& trial,
                      const Iterate& it) {
  const Vector6 r = space.compliance * (it.force - trial);
  const double weight =
      it.multiplier * it.potential.slope[static_cast<std::size_t>(g.contribution)];
  constexpr double kSlack = 1e-9;
  double zeta_sq = 0;
  for (int i = 0; i < 6; ++i) {
    if (!((g.components >> i) & 1u)) continue;
    const double scale = weight * g.coefficient[i];
    if (scale == 0) {
      const double bound = kTolerance * space.compliance(i, i) * it.yield.value;
      return std::abs(r[i]) <= bound ? 0.0 : std::abs(r[i]) / bound;
    }
    const double zeta = -r[i] / scale;
    if (g.macauley) return std::max({0.0, zeta - (1.0 + kSlack), -kSlack - zeta});
    zeta_sq += zeta * zeta;
  }
  return std::max(0.0, std::sqrt(zeta_sq) - (1.0 + kSlack));
}

}  // namespace

void closest_point_tangent(const ElasticSpace& space, const Vector6& normal,
                           const Matrix6& hessian, double multiplier, double hardening,
                           ComponentMask held, CoupledReturn& out) {
  Matrix6 a = SmallCholesky<6>(reduced_jacobian(space, hessian, multiplier, held)).inverse();
  Vector6 n = normal;
  if (held) {
    // A held group stays at zero under a small change of u (its ζ is strictly admissible), so
    // its rows and columns of the tangent vanish.
    const Vector6 free = mask_vector(~held);
    a = free.asDiagonal() * a * free.asDiagonal();
    n = n.cwiseProduct(free);
  }
  const Vector6 an = a * n;
  const double denominator = n.dot(an) + hardening;
  Matrix6 d = a;
  d.noalias() -= (an / denominator) * an.transpose();
  // Symmetric by construction; symmetrising removes the round-off of the solve.
  out.tangent = 0.5 * (d + d.transpose());
  out.yield_sensitivity = an / denominator;
}

CoupledReturn closest_point_return(const ElasticSpace& space, const ConnectorPotential& potential,
                                   YieldFunction yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent) {
  CoupledReturn out;
  out.force = trial;
  const double yield_old = yield.at(equivalent_old).value;
  // Step 1: the elastic test needs the value only.
  const double trial_value = potential.value(trial);
  if (!(trial_value - yield_old > 0)) return out;
  out.plastic = true;

  // R_λ is measured against F_y, but not below its round-off.
  const double floor = kReturnRoundOff * trial_value;
  const Scales scales{(space.compliance * trial).norm(), std::max(yield_old, floor), floor};
  const std::vector<KinkGroup>& groups = potential.kink_groups();
  // Kink groups held at zero (an active set on the kinks of P): a group is collapsed when a
  // Newton step overshoots it, and released when its subgradient condition fails at the
  // converged state. Releases are bounded so that the set cannot cycle.
  ComponentMask held = 0;
  int releases = 0;
  constexpr int kMaxReleases = 4;
  Iterate buffers[2];
  int cur = 0;
  buffers[cur].force = trial;
  buffers[cur].multiplier = 0;
  // At Δλ = 0 the Jacobian block is K⁻¹ alone, so the first iterate needs no Hessian.
  evaluate(space, potential, yield, trial, equivalent_old, scales, false, held, buffers[cur]);

  bool ok = false;
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    Iterate& it = buffers[cur];
    if (converged(it, scales)) {
      // One group at a time, the one whose subgradient is furthest from admissible: releasing
      // every inadmissible hold at once let a group that belongs at zero (and is held again by
      // the next step) pull the others across their kinks, and the active set cycled.
      ComponentMask released = 0;
      double worst = 0;
      for (const KinkGroup& g : groups) {
        if ((held & g.components) != g.components) continue;
        const double violation = hold_violation(g, space, trial, it);
        if (violation > worst) {
          worst = violation;
          released = g.components;
        }
      }
      if (!released) {
        ok = true;
        break;
      }
      // A hold that is still wrong after kMaxReleases releases: the active set cycles, and the
      // cutting plane takes over (§6.4 step 3).
      if (++releases > kMaxReleases) break;
      held = static_cast<ComponentMask>(held & ~released);
      // The released group leaves its kink along the trial force: at exactly zero the spec's
      // gradient of a NORM or Macaulay term is 0 and gives Newton no direction, and the line
      // search stalled there. 1e-6 of the trial moves the state by no more than the next step
      // corrects.
      for (int i = 0; i < 6; ++i) {
        if ((released >> i) & 1u) it.force[i] = kReleaseOffset * trial[i];
      }
      evaluate(space, potential, yield, trial, equivalent_old, scales, true, held, it);
    }
    // Newton on [K⁻¹ + Δλ N2, n; nᵀ, −h] (§6.4) by the Schur complement of the symmetric 6×6
    // block: a = M⁻¹ n, b = M⁻¹ R_F, δΔλ = (R_λ − nᵀ b)/(nᵀ a + h), δF = −b − a δΔλ. Held
    // components have identity rows and zero n and R_F, so their δF is 0.
    const SmallCholesky<6> llt(
        reduced_jacobian(space, it.potential.hessian, it.multiplier, held));
    if (!llt.ok()) break;
    const Vector6 n = held ? Vector6(it.potential.gradient.cwiseProduct(mask_vector(~held)))
                           : it.potential.gradient;
    const Vector6 a = llt.solve(n);
    const Vector6 b = llt.solve(it.residual_force);
    const double schur = n.dot(a) + it.yield.slope;
    if (!(schur > 0)) break;
    const double d_multiplier = (it.residual_yield - n.dot(b)) / schur;
    const Vector6 d_force = -b - a * d_multiplier;

    bool accepted = false;
    double t = 1.0;
    Iterate& next = buffers[1 - cur];
    for (int halving = 0; halving <= kMaxHalvings; ++halving, t *= 0.5) {
      next.force = it.force + t * d_force;
      next.multiplier = std::max(0.0, it.multiplier + t * d_multiplier);  // project Δλ ≥ 0
      ComponentMask crossed = 0;
      for (const KinkGroup& g : groups) {
        if (!(held & g.components) && crosses(g, it.force, next.force)) {
          crossed = static_cast<ComponentMask>(crossed | g.components);
        }
      }
      if (crossed) {
        // Stop the overshooting groups at their kink and go on with them held.
        held = static_cast<ComponentMask>(held | crossed);
        next.force = next.force.cwiseProduct(mask_vector(~held));
        evaluate(space, potential, yield, trial, equivalent_old, scales, true, held, next);
        accepted = true;
        break;
      }
      evaluate(space, potential, yield, trial, equivalent_old, scales, true, held, next);
      if (next.merit <= (1.0 - kArmijo * t) * it.merit) {
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
    cur = 1 - cur;
  }
  if (!ok) return cutting_plane_return(space, potential, yield, trial, equivalent_old, want_tangent);

  const Iterate& it = buffers[cur];
  out.force = it.force;
  out.multiplier = it.multiplier;
  if (want_tangent) {
    Matrix6 hessian = it.potential.hessian;
    // The first iterate was evaluated without the Hessian; it is the answer only when the trial
    // lay on the surface to round-off, and then Δλ = 0 and the Hessian is not used.
    if (it.multiplier == 0) hessian.setZero();
    closest_point_tangent(space, it.potential.gradient, hessian, it.multiplier, it.yield.slope,
                          held, out);
  }
  return out;
}

CoupledReturn cutting_plane_return(const ElasticSpace& space, const ConnectorPotential& potential,
                                   YieldFunction yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent) {
  CoupledReturn out;
  out.plastic = true;
  out.converged = false;
  Vector6 force = trial;
  double multiplier = 0;
  PotentialValue pv;
  const double floor = kReturnRoundOff * potential.value(trial);
  for (int iteration = 0; iteration <= kMaxCuttingPlaneIterations; ++iteration) {
    potential.evaluate(force, pv, false);
    const YieldSample y = yield.at(equivalent_old + multiplier);
    const double phi = pv.value - y.value;
    if (std::abs(phi) <= std::max(kTolerance * y.value, floor)) {
      out.converged = true;
      break;
    }
    if (iteration == kMaxCuttingPlaneIterations) break;
    const Vector6 kn = space.stiffness * pv.gradient;
    const double denominator = pv.gradient.dot(kn) + y.slope;
    if (!(denominator > 0)) break;
    const double step = phi / denominator;
    force -= step * kn;
    multiplier += step;
  }
  out.force = force;
  out.multiplier = multiplier;
  if (!out.converged) return out;
  if (want_tangent) {
    potential.evaluate(force, pv, true);
    closest_point_tangent(space, pv.gradient, pv.hessian, multiplier,
                          yield.at(equivalent_old + multiplier).slope, 0, out);
  }
  return out;
}

}  // namespace clinch
