// GroupedReturn::solve_lanes: the joint Newton of grouped_return.cpp (β = 1.5, every group
// uniform) for kLanes trial forces side by side. One return is a chain of dependent roots and
// divisions, so a core running one return at a time mostly waits on their latency; here every
// stage runs over all lanes before the next, as branch-free loops over lanes that the compiler
// vectorises. The kernel is compiled for three instruction sets and the widest the host has is
// picked when the program starts (target_clones); the file is built without FP contraction
// (CMakeLists.txt), so every clone rounds as the scalar code does and results do not depend on
// the host. A lane the Newton does not settle (a non-positive iterate, an active set that
// cycles on a kink, a vanished yield size) is handed to solve(), which has the nested solve to
// fall back on.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "src/behavior/bit_loop.hpp"
#include "src/behavior/grouped_return.hpp"

namespace clinch {
namespace {

constexpr int kLanes = GroupedReturn::kLanes;
// As solve_jointly, which takes 3–7 steps where it converges at all; a lane still iterating
// after these goes alone, so that it does not hold up the others.
constexpr int kJointIterations = 8;
constexpr double kTolerance = 1e-12;  // as grouped_return.cpp: on each Φ_i and on S − 1
constexpr double kBeta = 1.5;

using Lanes = double[kLanes];

// f(l) for every lane, as one loop that the compiler vectorises (OpenMP SIMD, -fopenmp-simd).
template <typename F>
[[gnu::always_inline]] inline void for_lanes(F&& f) {
#pragma omp simd
  for (int l = 0; l < kLanes; ++l) f(l);
}

// x^(1/3) for x ≥ 1 to a relative 3e-5, as approximate_cube_root of grouped_return.cpp but from
// the float exponent trick, which vectorises: it only shapes the first Δλ.
inline double cube_root_guess(double x) {
  const float f = static_cast<float>(x);
  const std::int32_t bits = std::bit_cast<std::int32_t>(f) / 3 + 709921077;
  const double y = std::bit_cast<float>(bits);
  const double y3 = y * y * y;
  return y * (y3 + 2 * x) / (2 * y3 + x);
}

// F_y and h at ū = x[l] on every lane: a tabular law without branches, the others by at().
[[gnu::always_inline]] inline void yield_at_lanes(const IsotropicHardeningLaw& yield,
                                                  const double* x, double* value, double* slope) {
  if (const PiecewiseLinearTable* table = yield.table()) {
    table->evaluate_lanes<kLanes>(x, value, slope);
    return;
  }
  for (int l = 0; l < kLanes; ++l) {
    const YieldSample s = yield.at(x[l]);
    value[l] = s.value;
    slope[l] = s.slope;
  }
}

// What became of a lane, held as a double so that every lane array has one element type and
// the loops over lanes vectorise.
constexpr double kElastic = 0, kIterating = 1, kConverged = 2, kAlone = 3;

}  // namespace

// GCC's function multiversioning: one clone per instruction set, picked at load time (other
// compilers build the baseline alone).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define CLINCH_LANE_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define CLINCH_LANE_CLONES
#endif

CLINCH_LANE_CLONES void GroupedReturn::solve_lanes(const IsotropicHardeningLaw& yield,
                                                   const Vector6* trial,
                                                   const double* equivalent_old, int count,
                                                   bool want_tangent, CoupledReturn* out) const {
  if (!has_lanes() || count < 2) {
    for (int l = 0; l < count; ++l) {
      out[l] = solve(yield, trial[l], equivalent_old[l], want_tangent);
    }
    return;
  }
  const int groups = group_count_, contributions = contribution_count_;
  // Lanes past `count` repeat the last trial and are not written out.
  Lanes force[6], ubar;  // F^tr, then F
  for (int l = 0; l < kLanes; ++l) {
    const int from = std::min(l, count - 1);
    ubar[l] = equivalent_old[from];
    for (int c = 0; c < 6; ++c) force[c][l] = trial[from][c];
  }
  Lanes trial_force[6];
  std::memcpy(trial_force, force, sizeof force);

  // The group resultants r_g and where each clips, r_g/κ_g (0 without flow).
  Lanes resultant[kMaxGroups], reach[kMaxGroups];
  for (int g = 0; g < groups; ++g) {
    const Group& gr = groups_[static_cast<std::size_t>(g)];
    double* r = resultant[g];
    if (gr.macauley || gr.single) {
      const int c = std::countr_zero(static_cast<unsigned>(gr.components));
      const double coefficient = gr.coefficient[c];
      for_lanes([&](int l) {
        const double x = coefficient * force[c][l];
        r[l] = gr.macauley ? std::max(0.0, x) : std::abs(x);
      });
    } else {
      for_lanes([&](int l) { r[l] = 0; });
      for_each_bit(gr.components, [&](int c) {
        const double coefficient = gr.coefficient[c];
        for_lanes([&](int l) {
          const double x = coefficient * force[c][l];
          r[l] += x * x;
        });
      });
      for_lanes([&](int l) { r[l] = std::sqrt(r[l]); });
    }
    for_lanes([&](int l) { reach[g][l] = r[l] * gr.inverse_kappa; });
  }
  // 1/r_g (0 without flow), for the forces and the tangent.
  Lanes inverse_resultant[kMaxGroups];
  for (int g = 0; g < groups; ++g) {
    for_lanes(
        [&](int l) { inverse_resultant[g][l] = resultant[g][l] > 0 ? 1 / resultant[g][l] : 0.0; });
  }

  // Per contribution: E_i^tr, K_i (κ of its positive groups) and the group that clips last,
  // whose piece an iterate past every clip continues (respond()); the yield check S > 1.
  Lanes yield_size, hardening, share_sum, inverse_yield;
  yield_at_lanes(yield, ubar, yield_size, hardening);
  for_lanes([&](int l) { inverse_yield[l] = 1 / yield_size[l]; });
  Lanes trial_sum[kMaxGroups], trial_kappa[kMaxGroups], last_reach[kMaxGroups],
      last_kappa[kMaxGroups];
  for_lanes([&](int l) { share_sum[l] = 0; });
  for (int i = 0; i < contributions; ++i) {
    const Contribution& ci = contributions_[static_cast<std::size_t>(i)];
    for_lanes([&](int l) {
      trial_sum[i][l] = trial_kappa[i][l] = last_reach[i][l] = last_kappa[i][l] = 0;
    });
    for_each_bit(ci.groups, [&](int g) {
      const double kappa = groups_[static_cast<std::size_t>(g)].kappa;
      for_lanes([&](int l) {
        trial_sum[i][l] += resultant[g][l];
        trial_kappa[i][l] += resultant[g][l] > 0 ? kappa : 0.0;
        const bool later = reach[g][l] > last_reach[i][l];
        last_kappa[i][l] = later ? kappa : last_kappa[i][l];
        last_reach[i][l] = later ? reach[g][l] : last_reach[i][l];
      });
    });
    for_lanes([&](int l) {
      const double z = trial_sum[i][l] * ci.inverse_scale * inverse_yield[l];
      share_sum[l] += z * std::sqrt(z);
    });
  }
  Lanes outcome;
  // A vanished yield size has no shares: solve() reports it.
  for_lanes([&](int l) {
    outcome[l] = !(yield_size[l] > 0) ? kAlone : share_sum[l] > 1 ? kIterating : kElastic;
  });
  auto count_iterating = [&] {
    int n = 0;
#pragma omp simd reduction(+ : n)
    for (int l = 0; l < kLanes; ++l) n += outcome[l] == kIterating ? 1 : 0;
    return n;
  };
  int iterating = count_iterating();

  // The first Δλ, the radial guess of grouped_return.cpp with one division:
  // Δλ = A (P^tr − F_y)/((P^tr)² + A h), A = Σ_i (E_i^tr)²/K_i, P^tr = F_y S^(2/3).
  Lanes multiplier, a = {};
  for (int i = 0; i < contributions; ++i) {
    for_lanes([&](int l) {
      const double e = trial_sum[i][l], k = trial_kappa[i][l];
      a[l] += k > 0 ? e * e / k : 0.0;
    });
  }
  for_lanes([&](int l) {
    const double s = outcome[l] == kIterating ? share_sum[l] : 2.0;  // any S > 1 for the others
    multiplier[l] = yield_size[l] * s / cube_root_guess(s);          // P^tr
  });
  for_lanes([&](int l) {
    const double p = multiplier[l];
    multiplier[l] = a[l] * (p - yield_size[l]) / (p * p + a[l] * hardening[l]);
    outcome[l] = !(multiplier[l] > 0) & (outcome[l] == kIterating) ? kAlone : outcome[l];
  });
  iterating = count_iterating();
  // Each v_i = √z_i solved at that Δλ with every positive group taken (a start only):
  // R_i F_y v² + (Δλ K_i/R_i) v − E_i = 0, in the form without cancellation.
  Lanes v[kMaxGroups], shifted;
  for_lanes([&](int l) { shifted[l] = ubar[l] + multiplier[l]; });
  yield_at_lanes(yield, shifted, yield_size, hardening);
  for (int i = 0; i < contributions; ++i) {
    const Contribution& ci = contributions_[static_cast<std::size_t>(i)];
    for_lanes([&](int l) {
      const double e = trial_sum[i][l];
      const double rf = ci.scale * yield_size[l];
      const double bk = multiplier[l] * trial_kappa[i][l] * ci.inverse_scale;
      v[i][l] = e > 0 ? 2 * e / (bk + std::sqrt(bk * bk + 4 * rf * e)) : 0.0;
    });
  }

  // The joint Newton of solve_jointly<true>, lane by lane in lock step. Per contribution at the
  // last iterate: y_i, 1/(∂Φ_i/∂v), ∂Φ_i/∂Δλ, and which groups stay positive is reach_g > y_i.
  Lanes y[kMaxGroups], inverse_a[kMaxGroups], rate_b[kMaxGroups], slope;
  for (int i = 0; i < contributions; ++i) {
    for_lanes([&](int l) { y[i][l] = inverse_a[i][l] = rate_b[i][l] = 0; });
  }
  for_lanes([&](int l) { slope[l] = 1; });
  for (int iteration = 0; iteration < kJointIterations && iterating > 0; ++iteration) {
    for_lanes([&](int l) { shifted[l] = ubar[l] + multiplier[l]; });
    yield_at_lanes(yield, shifted, yield_size, hardening);
    Lanes psi, weighted, next_slope, phi[kMaxGroups];
    Lanes settled, failed;  // 1 or 0
    for_lanes([&](int l) {
      psi[l] = -1;
      weighted[l] = next_slope[l] = 0;
      settled[l] = 1;
      failed[l] = (multiplier[l] > 0) & (yield_size[l] > 0) ? 0.0 : 1.0;
    });
    for (int i = 0; i < contributions; ++i) {
      const Contribution& ci = contributions_[static_cast<std::size_t>(i)];
      Lanes e, k;  // E_i(y_i) and K_i = −dE_i/dy_i
      for_lanes([&](int l) {
        y[i][l] = multiplier[l] * v[i][l] * ci.inverse_scale;
        e[l] = k[l] = 0;
      });
      for_each_bit(ci.groups, [&](int g) {
        const double kappa = groups_[static_cast<std::size_t>(g)].kappa;
        for_lanes([&](int l) {
          const bool positive = reach[g][l] > y[i][l];
          e[l] += positive ? resultant[g][l] - kappa * y[i][l] : 0.0;
          k[l] += positive ? kappa : 0.0;
        });
      });
      for_lanes([&](int l) {
        const bool flows = trial_sum[i][l] > 0;
        const bool extended = flows & (k[l] == 0);  // past the last clip (respond())
        e[l] = extended ? last_kappa[i][l] * (last_reach[i][l] - y[i][l]) : e[l];
        k[l] = extended ? last_kappa[i][l] : k[l];
        const double vi = v[i][l];
        const double rf = ci.scale * yield_size[l];
        const double kr = k[l] * ci.inverse_scale;
        const double z = vi * vi;
        const double inv_a = 1 / (2 * rf * vi + multiplier[l] * kr);
        const double q = flows ? 3 * z * inv_a : 0.0;
        phi[i][l] = flows ? rf * z - e[l] : 0.0;
        inverse_a[i][l] = flows ? inv_a : 0.0;
        rate_b[i][l] = flows ? ci.scale * hardening[l] * z + kr * vi : 0.0;
        psi[l] += z * vi;
        weighted[l] += q * phi[i][l];
        next_slope[l] += q * rate_b[i][l];
        failed[l] = flows & !(vi > 0) ? 1.0 : failed[l];
        settled[l] =
            !extended & (std::abs(phi[i][l]) <= kTolerance * trial_sum[i][l]) ? settled[l] : 0.0;
      });
    }
    for_lanes([&](int l) {
      const bool live = outcome[l] == kIterating;
      const bool fail = (failed[l] > 0) | !(next_slope[l] > 0);
      const bool done = (settled[l] > 0) & (std::abs(psi[l]) <= kBeta * kTolerance);
      outcome[l] = !live ? outcome[l] : fail ? kAlone : done ? kConverged : kIterating;
      slope[l] = live ? next_slope[l] : slope[l];
    });
    iterating = count_iterating();
    // Σ (∂z_i^β/∂v_i) dv_i = −(S − 1), dv_i = −(Φ_i + b_i dΔλ)/(∂Φ_i/∂v), on the lanes still
    // iterating; the others keep the iterate they stopped on. Near first yield Newton can
    // overshoot Δλ below zero: a step that would take it below a tenth of its value is
    // shortened to that, and the v_i follow their linearised response to the shorter step. A
    // share that turns non-positive (rare, far beyond yield) sends its lane alone.
    Lanes step;
    for_lanes([&](int l) {
      const double newton = outcome[l] == kIterating ? (psi[l] - weighted[l]) / next_slope[l] : 0.0;
      const double floor = -0.9 * multiplier[l];
      step[l] = newton < floor ? floor : newton;
      multiplier[l] += step[l];
    });
    for (int i = 0; i < contributions; ++i) {
      for_lanes([&](int l) {
        v[i][l] -=
            outcome[l] == kIterating ? (phi[i][l] + rate_b[i][l] * step[l]) * inverse_a[i][l] : 0.0;
      });
    }
  }
  // Not settled in kJointIterations.
  for_lanes([&](int l) { outcome[l] = outcome[l] == kIterating ? kAlone : outcome[l]; });

  // Forces of the converged lanes: F_c = t_c ⟨r_g − κ_g y_i⟩/r_g on a positive group, 0 on a
  // clipped one, t_c without flow (r_g = 0).
  for (int g = 0; g < groups; ++g) {
    const Group& gr = groups_[static_cast<std::size_t>(g)];
    const double kappa = gr.kappa;
    const double* yi = y[gr.contribution];
    Lanes ratio;
    for_lanes([&](int l) {
      const double r = resultant[g][l];
      const double shrunk =
          reach[g][l] > yi[l] ? (r - kappa * yi[l]) * inverse_resultant[g][l] : 0.0;
      ratio[l] = (r > 0) & (outcome[l] == kConverged) ? shrunk : 1.0;
    });
    for_each_bit(gr.components, [&](int c) { for_lanes([&](int l) { force[c][l] *= ratio[l]; }); });
  }
  for (int l = 0; l < count; ++l) {
    CoupledReturn& o = out[l];
    if (outcome[l] == kAlone) {
      o = solve(yield, trial[l], equivalent_old[l], want_tangent);
      continue;
    }
    o.plastic = outcome[l] == kConverged;  // the tangent is written below where it is
    o.converged = true;
    o.multiplier = o.plastic ? multiplier[l] : 0.0;
    for (int c = 0; c < 6; ++c) o.force[c] = force[c][l];
  }
  bool converged = false;
  for (int l = 0; l < count; ++l) converged = converged || outcome[l] == kConverged;
  if (!want_tangent || !converged) return;

  // The consistent tangent of the uniform case of GroupedReturn::tangent (derivation there):
  // row c = (T_g/r_g) k_c e_c + row_c (Y_i W + X_i N over contribution i) + own_c N over group g.
  Lanes x[kMaxGroups], yy[kMaxGroups], weight[kMaxGroups], inverse_slope;
  for_lanes([&](int l) { inverse_slope[l] = 1 / slope[l]; });
  for (int i = 0; i < contributions; ++i) {
    const double inverse_scale = contributions_[static_cast<std::size_t>(i)].inverse_scale;
    for_lanes([&](int l) {
      x[i][l] = multiplier[l] * inverse_a[i][l] * inverse_scale;
      yy[i][l] = v[i][l] * inverse_scale - x[i][l] * rate_b[i][l];
      weight[i][l] = kBeta * v[i][l] * 2 * v[i][l] * inverse_a[i][l] * inverse_slope[l];
    });
  }
  Lanes n[6], w[6], row_y[6], row_x[6], own[6], diagonal[6];
  for (int c = 0; c < 6; ++c) {  // a component outside the potential: zero rows and columns
    if (group_of_[static_cast<std::size_t>(c)] >= 0) continue;
    for_lanes([&](int l) { n[c][l] = w[c][l] = row_y[c][l] = row_x[c][l] = 0; });
    for_lanes([&](int l) { own[c][l] = diagonal[c][l] = 0; });
  }
  for (int g = 0; g < groups; ++g) {
    const Group& gr = groups_[static_cast<std::size_t>(g)];
    const int i = gr.contribution;
    for_each_bit(gr.components, [&](int c) {
      const double stiffness = stiffness_[c], c2 = gr.coefficient[c] * gr.coefficient[c];
      for_lanes([&](int l) {
        const double r = resultant[g][l];
        const bool positive = (r > 0) & (reach[g][l] > y[i][l]);
        const double inv_r = positive ? inverse_resultant[g][l] : 0.0;
        const double t = trial_force[c][l];
        const double kr = gr.kappa * inv_r;
        const double row = -t * kr;
        n[c][l] = c2 * t * inv_r * stiffness;
        w[c][l] = weight[i][l] * n[c][l];
        row_y[c][l] = row * yy[i][l];
        row_x[c][l] = row * x[i][l];
        own[c][l] = t * kr * y[i][l] * inv_r;
        diagonal[c][l] = positive ? (r - gr.kappa * y[i][l]) * inv_r * stiffness
                         : r > 0  ? 0.0
                                  : stiffness;  // no flow: F = t
      });
    });
  }
  // The upper triangle, mirrored: the tangent is symmetric in exact arithmetic (associated
  // flow), so this is GroupedReturn::tangent's symmetric mean to round-off.
  Lanes tangent[6][6];
  for (int c = 0; c < 6; ++c) {
    for (int e = c; e < 6; ++e) {
      const double same_contribution = same_contribution_(c, e), same_group = same_group_(c, e);
      const double on_diagonal = c == e ? 1.0 : 0.0;
      for_lanes([&](int l) {
        tangent[c][e][l] = tangent[e][c][l] =
            row_y[c][l] * w[e][l] + same_contribution * row_x[c][l] * n[e][l] +
            same_group * own[c][l] * n[e][l] + on_diagonal * diagonal[c][l];
      });
    }
  }
  for (int l = 0; l < count; ++l) {
    if (outcome[l] != kConverged) continue;
    for (int e = 0; e < 6; ++e) {
      for (int c = 0; c < 6; ++c) out[l].tangent(c, e) = tangent[c][e][l];
    }
  }
}

}  // namespace clinch
