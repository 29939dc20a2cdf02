#include "src/behavior/coupled_return_mapping.hpp"

#include <algorithm>
#include <cmath>

namespace clinch {
namespace {

constexpr int kMaxNewtonIterations = 30;         // §6.4 step 2
constexpr int kMaxHalvings = 10;                 // §6.4 step 2
constexpr int kMaxCuttingPlaneIterations = 200;  // §6.4 step 3
constexpr double kTolerance = 1e-12;             // §6.4 steps 2 and 3
// Armijo constant of the backtracking line search: any decrease proportional to the step is
// enough; the merit only guards Newton against overshooting a kink of the potential.
constexpr double kArmijo = 1e-4;

// One iterate of the closest-point Newton: (F, Δλ), P and its derivatives at F, F_y and h at
// ū_n + Δλ, the residuals of §6.4 and the merit.
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
  double force;   // F_y(ū_n)
};

void evaluate(const ElasticSpace& space, const ConnectorPotential& potential,
              const IsotropicHardeningLaw& yield, const Vector6& trial, double equivalent_old,
              const Scales& scales, bool hessian, Iterate& it) {
  potential.evaluate(it.force, it.potential, hessian);
  it.yield = yield.at(equivalent_old + it.multiplier);
  it.residual_force.noalias() = space.compliance * (it.force - trial);
  it.residual_force += it.multiplier * it.potential.gradient;
  it.residual_yield = it.potential.value - it.yield.value;
  // §6.4 asks for ‖R_F‖² + (R_λ/F_y)²; R_F is divided by its own stopping scale too, so that the
  // two terms are dimensionless and weighted as the stopping test weights them.
  const double rf = it.residual_force.norm() / scales.motion;
  const double rl = it.residual_yield / scales.force;
  it.merit = rf * rf + rl * rl;
}

bool converged(const Iterate& it, const Scales& scales) {
  return it.residual_force.norm() <= kTolerance * scales.motion &&
         std::abs(it.residual_yield) <= kTolerance * it.yield.value;
}

}  // namespace

Matrix6 closest_point_tangent(const ElasticSpace& space, const Vector6& normal,
                              const Matrix6& hessian, double multiplier, double hardening) {
  Matrix6 m = space.compliance;
  if (multiplier > 0) m += multiplier * hessian;
  const Eigen::LLT<Matrix6> llt(m);
  const Matrix6 a = llt.solve(Matrix6::Identity());
  const Vector6 an = a * normal;
  const double denominator = normal.dot(an) + hardening;
  Matrix6 d = a;
  d.noalias() -= (an / denominator) * an.transpose();
  // Symmetric by construction; symmetrising removes the round-off of the solve.
  return 0.5 * (d + d.transpose());
}

CoupledReturn closest_point_return(const ElasticSpace& space, const ConnectorPotential& potential,
                                   const IsotropicHardeningLaw& yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent) {
  CoupledReturn out;
  out.force = trial;
  const double yield_old = yield.at(equivalent_old).value;
  // Step 1: the elastic test needs the value only.
  if (!(potential.value(trial) - yield_old > 0)) return out;
  out.plastic = true;

  const Scales scales{(space.compliance * trial).norm(), yield_old};
  Iterate buffers[2];
  int cur = 0;
  buffers[cur].force = trial;
  buffers[cur].multiplier = 0;
  // At Δλ = 0 the Jacobian block is K⁻¹ alone, so the first iterate needs no Hessian.
  evaluate(space, potential, yield, trial, equivalent_old, scales, false, buffers[cur]);

  bool ok = false;
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    const Iterate& it = buffers[cur];
    if (converged(it, scales)) {
      ok = true;
      break;
    }
    // Newton on [K⁻¹ + Δλ N2, n; nᵀ, −h] (§6.4) by the Schur complement of the symmetric 6×6
    // block: a = M⁻¹ n, b = M⁻¹ R_F, δΔλ = (R_λ − nᵀ b)/(nᵀ a + h), δF = −b − a δΔλ.
    Matrix6 m = space.compliance;
    if (it.multiplier > 0) m += it.multiplier * it.potential.hessian;
    const Eigen::LLT<Matrix6> llt(m);
    if (llt.info() != Eigen::Success) break;
    const Vector6& n = it.potential.gradient;
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
      evaluate(space, potential, yield, trial, equivalent_old, scales, true, next);
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
    out.tangent = closest_point_tangent(space, it.potential.gradient, hessian, it.multiplier,
                                        it.yield.slope);
  }
  return out;
}

CoupledReturn cutting_plane_return(const ElasticSpace& space, const ConnectorPotential& potential,
                                   const IsotropicHardeningLaw& yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent) {
  CoupledReturn out;
  out.plastic = true;
  out.converged = false;
  Vector6 force = trial;
  double multiplier = 0;
  PotentialValue pv;
  for (int iteration = 0; iteration <= kMaxCuttingPlaneIterations; ++iteration) {
    potential.evaluate(force, pv, false);
    const YieldSample y = yield.at(equivalent_old + multiplier);
    const double phi = pv.value - y.value;
    if (std::abs(phi) <= kTolerance * y.value) {
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
    out.tangent = closest_point_tangent(space, pv.gradient, pv.hessian, multiplier,
                                        yield.at(equivalent_old + multiplier).slope);
  }
  return out;
}

}  // namespace clinch
