#include "src/behavior/plastic/multi_surface_return.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "src/behavior/plastic/coupled_return_mapping.hpp"
#include "base/small_cholesky.hpp"

namespace clinch {
namespace {

constexpr int kMaxSetChanges = 10;       // §6.6
constexpr int kMaxNewtonIterations = 30;  // as §6.4 step 2
constexpr int kMaxHalvings = 10;
constexpr double kTolerance = 1e-12;
// A surface outside the active set is added when φ_i > 1e-11·F_y: above the 1e-12 stopping
// tolerance of the active ones, so that round-off at a corner cannot make the set cycle.
constexpr double kAddTolerance = 1e-11;
constexpr double kArmijo = 1e-4;
// At most six surfaces can be active with independent normals in six components.
constexpr int kMaxActive = 6;
// Two normals are parallel when |cos| ≥ 1 − 1e-10 (§6.6 parallel-normal rule).
constexpr double kParallel = 1e-10;

struct ActiveSet {
  std::array<int, kMaxActive> surface{};
  int size = 0;
};

struct Iterate {
  Vector6 force;
  std::array<double, kMaxActive> multiplier{};
  std::array<PotentialValue, kMaxActive> surface;
  YieldSample yield;
  Vector6 residual_force;
  std::array<double, kMaxActive> residual{};
  double merit = 0;
  double total() const {
    double s = 0;
    for (double m : multiplier) s += m;
    return s;
  }
};

struct Context {
  const ElasticSpace& space;
  const ConnectorPotential& potential;
  YieldFunction yield;
  const Vector6& trial;
  double equivalent_old;
  double motion_scale;  // ‖K⁻¹ F^tr‖
  double force_scale;   // F_y(ū_n), at least `floor`
  double floor;         // the round-off of the φ_j: kReturnRoundOff·P(F^tr)
};

void evaluate(const Context& c, const ActiveSet& set, bool hessian, Iterate& it) {
  it.yield = c.yield.at(c.equivalent_old + it.total());
  it.residual_force.noalias() = c.space.compliance * (it.force - c.trial);
  double merit = 0;
  for (int j = 0; j < set.size; ++j) {
    const auto js = static_cast<std::size_t>(j);
    PotentialValue& pv = it.surface[js];
    c.potential.evaluate_contribution(set.surface[js], it.force, pv, hessian);
    it.residual_force += it.multiplier[js] * pv.gradient;
    it.residual[js] = pv.value - it.yield.value;
    const double r = it.residual[js] / c.force_scale;
    merit += r * r;
  }
  const double rf = it.residual_force.norm() / c.motion_scale;
  it.merit = merit + rf * rf;
}

bool converged(const Context& c, const ActiveSet& set, const Iterate& it) {
  if (it.residual_force.norm() > kTolerance * c.motion_scale) return false;
  for (int j = 0; j < set.size; ++j) {
    if (std::abs(it.residual[static_cast<std::size_t>(j)]) >
        std::max(kTolerance * it.yield.value, c.floor)) {
      return false;
    }
  }
  return true;
}

bool parallel(const Vector6& a, const Vector6& b) {
  const double na = a.norm(), nb = b.norm();
  return na > 0 && nb > 0 && std::abs(a.dot(b)) >= (1.0 - kParallel) * na * nb;
}

// M = K⁻¹ + Σ Δλ_j N2_j, the symmetric 6×6 block of the Jacobian.
Matrix6 block(const Context& c, const ActiveSet& set, const Iterate& it) {
  Matrix6 m = c.space.compliance;
  for (int j = 0; j < set.size; ++j) {
    const auto js = static_cast<std::size_t>(j);
    if (it.multiplier[js] > 0) m += it.multiplier[js] * it.surface[js].hessian;
  }
  return m;
}

// The Newton step by the Schur complement: with A_N = M⁻¹ N and b = M⁻¹ R_F,
// (Nᵀ A_N + h 1 1ᵀ) δΔλ = R_J − Nᵀ b and δF = −b − A_N δΔλ. Unused rows of the 6×6 Schur
// matrix are the identity. False when it is singular (parallel normals).
bool newton_step(const ActiveSet& set, const Iterate& it, const Matrix6& m, Vector6& d_force,
                 Vector6& d_multiplier) {
  const SmallCholesky<6> llt(m);
  if (!llt.ok()) return false;
  Matrix6 an = Matrix6::Zero();
  Matrix6 schur = Matrix6::Identity();
  Vector6 rhs = Vector6::Zero();
  const Vector6 b = llt.solve(it.residual_force);
  for (int j = 0; j < set.size; ++j) {
    an.col(j) = llt.solve(it.surface[static_cast<std::size_t>(j)].gradient);
  }
  for (int i = 0; i < set.size; ++i) {
    const Vector6& ni = it.surface[static_cast<std::size_t>(i)].gradient;
    for (int j = 0; j < set.size; ++j) schur(i, j) = ni.dot(an.col(j)) + it.yield.slope;
    rhs[i] = it.residual[static_cast<std::size_t>(i)] - ni.dot(b);
  }
  const Eigen::LDLT<Matrix6> ldlt(schur);
  const auto& pivots = ldlt.vectorD();
  const double largest = pivots.cwiseAbs().maxCoeff();
  if (ldlt.info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * largest)) return false;
  d_multiplier = ldlt.solve(rhs);
  d_force = -b - an * d_multiplier;
  return true;
}

enum class SolveResult { Converged, Singular, Failed };

// Newton on (F, Δλ_J) for a fixed active set, from (F^tr, 0).
SolveResult solve(const Context& c, const ActiveSet& set, Iterate buffers[2], int& cur) {
  cur = 0;
  Iterate& first = buffers[0];
  first.force = c.trial;
  first.multiplier.fill(0.0);
  evaluate(c, set, true, first);
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    const Iterate& it = buffers[cur];
    if (converged(c, set, it)) return SolveResult::Converged;
    Vector6 d_force, d_multiplier;
    if (!newton_step(set, it, block(c, set, it), d_force, d_multiplier)) {
      return SolveResult::Singular;
    }
    Iterate& next = buffers[1 - cur];
    bool accepted = false;
    double t = 1.0;
    for (int halving = 0; halving <= kMaxHalvings; ++halving, t *= 0.5) {
      next.force = it.force + t * d_force;
      next.multiplier.fill(0.0);
      // Each Δλ_j moves freely inside a set: a negative one is the signal to drop surface j.
      for (int j = 0; j < set.size; ++j) {
        const auto js = static_cast<std::size_t>(j);
        next.multiplier[js] = it.multiplier[js] + t * d_multiplier[j];
      }
      evaluate(c, set, true, next);
      if (next.merit <= (1.0 - kArmijo * t) * it.merit) {
        accepted = true;
        break;
      }
    }
    if (!accepted) return SolveResult::Failed;
    cur = 1 - cur;
  }
  return converged(c, set, buffers[cur]) ? SolveResult::Converged : SolveResult::Failed;
}

// Insertion sort of the (at most six) active surfaces by index: data-line order keeps the
// parallel-normal tie rule and the iteration deterministic.
void sort_by_index(ActiveSet& set) {
  for (int i = 1; i < set.size; ++i) {
    const int v = set.surface[static_cast<std::size_t>(i)];
    int j = i - 1;
    for (; j >= 0 && set.surface[static_cast<std::size_t>(j)] > v; --j) {
      set.surface[static_cast<std::size_t>(j + 1)] = set.surface[static_cast<std::size_t>(j)];
    }
    set.surface[static_cast<std::size_t>(j + 1)] = v;
  }
}

void remove_at(ActiveSet& set, int position) {
  for (int j = position; j + 1 < set.size; ++j) {
    set.surface[static_cast<std::size_t>(j)] = set.surface[static_cast<std::size_t>(j + 1)];
  }
  --set.size;
}

// The active surface with the smallest φ_i = s_i P_i − F_y at `force` (its index in `set`).
int least_violated(const Context& c, const ActiveSet& set, const Vector6& force) {
  int least = 0;
  double lowest = 0;
  PotentialValue pv;
  for (int j = 0; j < set.size; ++j) {
    c.potential.evaluate_contribution(set.surface[static_cast<std::size_t>(j)], force, pv, false);
    if (j == 0 || pv.value < lowest) {
      lowest = pv.value;
      least = j;
    }
  }
  return least;
}

// §6.6 parallel-normal rule at `force`: of two active surfaces with parallel normals only one is
// kept. The spec keeps the lowest index; clinch keeps the one with the larger φ and uses the
// lowest index only on a tie, because a parallel but distinct surface below the binding one can
// never be active at the solution. True when a surface was removed.
bool drop_parallel(const Context& c, ActiveSet& set, const Vector6& force) {
  std::array<PotentialValue, kMaxActive> pv;
  for (int j = 0; j < set.size; ++j) {
    c.potential.evaluate_contribution(set.surface[static_cast<std::size_t>(j)], force,
                                      pv[static_cast<std::size_t>(j)], false);
  }
  for (int i = 0; i < set.size; ++i) {
    for (int j = i + 1; j < set.size; ++j) {
      const PotentialValue& a = pv[static_cast<std::size_t>(i)];
      const PotentialValue& b = pv[static_cast<std::size_t>(j)];
      if (!parallel(a.gradient, b.gradient)) continue;
      const double tie = 1e-12 * std::max(std::abs(a.value), std::abs(b.value));
      const bool keep_j = b.value > a.value + tie;
      remove_at(set, keep_j ? i : j);
      return true;
    }
  }
  return false;
}

}  // namespace

CoupledReturn multi_surface_return(const ElasticSpace& space, const ConnectorPotential& potential,
                                   YieldFunction yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent) {
  CoupledReturn out;
  out.force = trial;
  const double yield_old = yield.at(equivalent_old).value;
  const int count = potential.contribution_count();

  // J = {i : φ_i^tr > 0}. When more than six are violated the most violated ones are kept.
  ActiveSet set;
  PotentialValue pv;
  std::array<double, kMaxActive> excess{};
  for (int i = 0; i < count; ++i) {
    potential.evaluate_contribution(i, trial, pv, false);
    const double phi = pv.value - yield_old;
    if (!(phi > 0)) continue;
    if (set.size < kMaxActive) {
      excess[static_cast<std::size_t>(set.size)] = phi;
      set.surface[static_cast<std::size_t>(set.size++)] = i;
      continue;
    }
    // Full: replace the least violated surface if this one is more violated.
    const auto least = std::min_element(excess.begin(), excess.end()) - excess.begin();
    if (phi > excess[static_cast<std::size_t>(least)]) {
      excess[static_cast<std::size_t>(least)] = phi;
      set.surface[static_cast<std::size_t>(least)] = i;
    }
  }
  if (set.size == 0) return out;
  out.plastic = true;
  sort_by_index(set);
  // The φ_j are measured against F_y, but not below their round-off.
  const double floor = kReturnRoundOff * potential.value(trial);
  const Context c{space, potential, yield, trial, equivalent_old,
                  (space.compliance * trial).norm(), std::max(yield_old, floor), floor};
  while (drop_parallel(c, set, trial)) {
  }

  Iterate buffers[2];
  int cur = 0;
  bool done = false;
  for (int change = 0; change <= kMaxSetChanges && !done; ++change) {
    const SolveResult r = solve(c, set, buffers, cur);
    if (r == SolveResult::Singular) {
      // Dependent normals: parallel ones (§6.6), or more active surfaces than the components
      // they span (three surfaces through a corner of a two-component section). The least
      // violated surface at the current force leaves the set; if it is needed, the add step
      // below brings it back.
      if (!drop_parallel(c, set, buffers[cur].force)) {
        if (set.size <= 1) break;
        remove_at(set, least_violated(c, set, buffers[cur].force));
      }
      continue;
    }
    if (r == SolveResult::Failed) break;
    const Iterate& it = buffers[cur];
    // Drop the surface with the most negative multiplier, if any.
    int most_negative = -1;
    double lowest = 0;
    for (int j = 0; j < set.size; ++j) {
      const double m = it.multiplier[static_cast<std::size_t>(j)];
      if (m < lowest) {
        lowest = m;
        most_negative = j;
      }
    }
    if (most_negative >= 0) {
      remove_at(set, most_negative);
      if (set.size == 0) break;
      continue;
    }
    // Add the most violated surface outside J, if any.
    int worst = -1;
    double worst_phi = std::max(kAddTolerance * it.yield.value, 10 * c.floor);
    for (int i = 0; i < count; ++i) {
      if (std::find(set.surface.begin(), set.surface.begin() + set.size, i) !=
          set.surface.begin() + set.size) {
        continue;
      }
      potential.evaluate_contribution(i, it.force, pv, false);
      const double phi = pv.value - it.yield.value;
      if (phi > worst_phi) {
        worst_phi = phi;
        worst = i;
      }
    }
    if (worst < 0) {
      done = true;
      break;
    }
    if (set.size == kMaxActive) break;
    set.surface[static_cast<std::size_t>(set.size++)] = worst;
    sort_by_index(set);
  }
  if (!done) {
    // The cutting plane follows the maximising contribution (§6.4 step 3 as the fallback).
    return cutting_plane_return(space, potential, yield, trial, equivalent_old, want_tangent);
  }

  const Iterate& it = buffers[cur];
  out.force = it.force;
  out.multiplier = it.total();
  if (!want_tangent) return out;
  // §6.6: D = A − A N (Nᵀ A N + h 1 1ᵀ)⁻¹ Nᵀ A with A = M⁻¹ at the converged state.
  const Matrix6 a = SmallCholesky<6>(block(c, set, it)).inverse();
  Matrix6 an = Matrix6::Zero();
  Matrix6 schur = Matrix6::Identity();
  for (int j = 0; j < set.size; ++j) an.col(j) = a * it.surface[static_cast<std::size_t>(j)].gradient;
  for (int i = 0; i < set.size; ++i) {
    for (int j = 0; j < set.size; ++j) {
      schur(i, j) = it.surface[static_cast<std::size_t>(i)].gradient.dot(an.col(j)) +
                    it.yield.slope;
    }
  }
  const Eigen::LDLT<Matrix6> ldlt(schur);
  Matrix6 d = a - an * ldlt.solve(an.transpose());
  out.tangent = 0.5 * (d + d.transpose());
  // A shift δ of F_y at fixed u: Nᵀ dF − h 1 1ᵀ dΔλ = δ 1 with dF = −A N dΔλ.
  Vector6 ones = Vector6::Zero();
  ones.head(set.size).setOnes();
  out.yield_sensitivity = an * ldlt.solve(ones);
  return out;
}

}  // namespace clinch
