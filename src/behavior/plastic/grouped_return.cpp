#include "src/behavior/plastic/grouped_return.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "src/behavior/bit_loop.hpp"

namespace clinch {
namespace {

constexpr int kMaxIterations = 60;    // Newton with bisection: far more than it ever needs
constexpr double kTolerance = 1e-12;  // on P/F_y − 1 (§6.4); |S − 1| ≤ β·kTolerance
// Within this distance of S = 1, S^γ is taken from its series (GroupedReturn::distance).
constexpr double kNearSurface = 1e-2;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// x^(1/3) for a positive normal x to a relative 3e-5: an exponent-thirding first guess (3%) and
// one Halley step, which cubes the error. It only shapes the guess and the steps of the outer
// Newton far from the surface (convergence is tested on exact quantities), where std::cbrt cost
// as much as an evaluation of the shares.
double approximate_cube_root(double x) {
  if (!(x >= std::numeric_limits<double>::min() && x <= std::numeric_limits<double>::max())) {
    return std::cbrt(x);
  }
  const double y =
      std::bit_cast<double>(std::bit_cast<std::uint64_t>(x) / 3 + 0x2A9F7893782DA1CEull);
  const double y3 = y * y * y;
  return y * (y3 + 2 * x) / (2 * y3 + x);
}

}  // namespace

// Some groups of one contribution that stay positive: their bits, Σ r_g, Σ κ_g, and the
// smallest y_i at which one of them clips.
struct GroupedReturn::GroupSet {
  unsigned mask = 0;
  double sum = 0, kappa = 0;
  double first_clip = std::numeric_limits<double>::infinity();
};

// What a return needs of the trial force: the group resultants r_g and, per contribution, its
// groups with r_g > 0.
struct GroupedReturn::Trial {
  Vector6 force;                             // F^tr
  std::array<double, kMaxGroups> resultant;  // r_g
  std::array<double, kMaxGroups> inverse;    // 1/r_g (0 for r_g = 0)
  std::array<double, kMaxGroups> reach;      // the y_i at which group g clips (r_g/κ_g if uniform)
  // κ_g of a uniform group; of a non-uniform one −dT_g/dy at y = 0, Σ_c a_c κ_c/r_g² (a_c below)
  std::array<double, kMaxGroups> kappa;
  std::array<GroupSet, kMaxGroups> positive;
};

// E_i and K_i = −dE_i/dy_i of one contribution at a given y_i, from the groups that stay
// positive (`mask`); `extended` where all have clipped and the last one's piece is continued.
struct GroupedReturn::Response {
  double force = 0, rate = 0;
  unsigned mask = 0;
  bool extended = false;
};

// One contribution at a given Δλ: its share z = E_i/(R_i F_y), z^(β−1), the derivatives of its
// equation Φ_i = R_i F_y z + Δλ K_i z^(β−1)/R_i − Σ_g r_g, y_i = Δλ n_i, and which of its
// groups stay positive. Every field is written by solve_share.
struct GroupedReturn::Share {
  double z;
  double zb1;         // z^(β−1)
  double inv_a;       // 1/(∂Φ_i/∂z)
  double dzb1_inv_a;  // (z^(β−1))′/(∂Φ_i/∂z)
  double b;           // ∂Φ_i/∂Δλ
  double y;           // Δλ n_i
  double curvature;   // d²(z^β)/dΔλ² (β = 1.5 only; NaN otherwise)
  unsigned active;    // bits of the groups (indices into groups_) with T_g > 0
};

struct GroupedReturn::Iterate {
  std::array<Share, kMaxGroups> share;
  // Per group: T_g and −dT_g/dy_i at the iterate (0 where clipped).
  std::array<double, kMaxGroups> group_force{}, group_rate{};
  double sum = 0;        // S = Σ z_i^β
  double slope = 0;      // Q = −dS/dΔλ = Σ β z_i^(β−1) (∂Φ_i/∂Δλ)/(∂Φ_i/∂z)
  double curvature = 0;  // d²S/dΔλ² (NaN where not formed)
};

std::optional<GroupedReturn> GroupedReturn::create(const ConnectorPotential& potential,
                                                   const ElasticSpace& space) {
  std::vector<KinkGroup> groups;
  std::vector<double> scales;
  if (!potential.group_structure(groups, scales)) return std::nullopt;
  if (static_cast<int>(scales.size()) > kMaxGroups ||
      static_cast<int>(groups.size()) > kMaxGroups) {
    return std::nullopt;
  }
  const Matrix6& k = space.stiffness;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      if (i != j && k(i, j) != 0) return std::nullopt;  // K must be diagonal
    }
  }
  GroupedReturn out;
  out.stiffness_ = k.diagonal();
  // Groups ordered by contribution, so that each contribution owns a range.
  std::stable_sort(groups.begin(), groups.end(), [](const KinkGroup& a, const KinkGroup& b) {
    return a.contribution < b.contribution;
  });
  out.contribution_count_ = static_cast<int>(scales.size());
  for (const KinkGroup& g : groups) {
    Group r;
    r.components = g.components;
    r.macauley = g.macauley;
    r.single = std::popcount(static_cast<unsigned>(g.components)) == 1;
    r.contribution = g.contribution;
    r.coefficient = g.coefficient;
    bool first = true;
    for (int c = 0; c < 6; ++c) {
      if (!((g.components >> c) & 1u)) continue;
      const double kappa = k(c, c) * g.coefficient[c] * g.coefficient[c];
      if (!(kappa > 0)) return std::nullopt;
      r.component_kappa[c] = kappa;
      if (first) {
        r.kappa = kappa;
        first = false;
      } else if (std::abs(kappa - r.kappa) > 1e-12 * r.kappa) {
        r.uniform = false;  // the flow is not radial in this group
      }
    }
    r.inverse_kappa = 1 / r.kappa;
    out.nonuniform_ = out.nonuniform_ || !r.uniform;
    for (int c = 0; c < 6; ++c) {
      if ((g.components >> c) & 1u)
        out.group_of_[static_cast<std::size_t>(c)] = static_cast<std::int8_t>(out.group_count_);
    }
    out.groups_[static_cast<std::size_t>(out.group_count_++)] = r;
  }
  for (int c = 0; c < 6; ++c) {
    const int g = out.group_of_[static_cast<std::size_t>(c)];
    if (g >= 0) out.contribution_of_[c] = out.groups_[static_cast<std::size_t>(g)].contribution;
  }
  for (int c = 0; c < 6; ++c) {
    for (int e = 0; e < 6; ++e) {
      if (out.group_of_[static_cast<std::size_t>(c)] < 0 ||
          out.group_of_[static_cast<std::size_t>(e)] < 0)
        continue;
      out.same_group_(c, e) =
          out.group_of_[static_cast<std::size_t>(c)] == out.group_of_[static_cast<std::size_t>(e)];
      out.same_contribution_(c, e) = out.contribution_of_[c] == out.contribution_of_[e];
    }
  }
  int next = 0;
  for (int i = 0; i < out.contribution_count_; ++i) {
    Contribution& c = out.contributions_[static_cast<std::size_t>(i)];
    c.scale = scales[static_cast<std::size_t>(i)];
    c.inverse_scale = 1 / c.scale;
    while (next < out.group_count_ &&
           out.groups_[static_cast<std::size_t>(next)].contribution == i) {
      c.groups |= 1u << next++;
    }
  }
  out.beta_ = potential.exponent();
  out.gamma_ = 1 - 1 / out.beta_;
  out.exponent_ = out.beta_ == 1.0   ? Exponent::One
                  : out.beta_ == 1.5 ? Exponent::ThreeHalves
                  : out.beta_ == 2.0 ? Exponent::Two
                                     : Exponent::General;
  // A non-uniform group has no closed-form share: only the joint Newton (β = 1.5, 2) takes it.
  if (out.nonuniform_ && out.exponent_ != Exponent::ThreeHalves && out.exponent_ != Exponent::Two) {
    return std::nullopt;
  }
  return out;
}

// S^γ (γ = 1 − 1/β), for the guess and the far steps only: the cube root is approximate.
double GroupedReturn::root_of_share_sum(double s) const {
  switch (exponent_) {
    case Exponent::One:
      return 1;
    case Exponent::ThreeHalves:
      return approximate_cube_root(s);
    case Exponent::Two:
      return std::sqrt(s);
    case Exponent::General:
      break;
  }
  return std::pow(s, gamma_);
}

void GroupedReturn::resolve_resultants(const Vector6& trial, Trial& t) const {
  t.force = trial;
  for (int g = 0; g < group_count_; ++g) {
    const Group& gr = groups_[static_cast<std::size_t>(g)];
    double v = 0;
    for_each_bit(gr.components, [&](int c) {
      const double x = gr.coefficient[c] * trial[c];
      v = gr.macauley ? std::max(0.0, x) : gr.single ? std::abs(x) : v + x * x;
    });
    // A Macaulay group: its positive part (a negative one has no flow).
    t.resultant[static_cast<std::size_t>(g)] = gr.macauley || gr.single ? v : std::sqrt(v);
  }
}

double GroupedReturn::trial_share_sum(const Trial& t, double yield_size) const {
  const double inverse_yield = 1 / yield_size;
  double sum = 0;
  int g = 0;
  for (int i = 0; i < contribution_count_; ++i) {
    double e = 0;  // E_i^tr: the groups of a contribution are consecutive
    for (; g < group_count_ && groups_[static_cast<std::size_t>(g)].contribution == i; ++g) {
      e += t.resultant[static_cast<std::size_t>(g)];
    }
    const double z = e * contributions_[static_cast<std::size_t>(i)].inverse_scale * inverse_yield;
    switch (exponent_) {
      case Exponent::One:
        sum += z;
        break;
      case Exponent::ThreeHalves:
        sum += z * std::sqrt(z);
        break;
      case Exponent::Two:
        sum += z * z;
        break;
      case Exponent::General:
        sum += std::pow(z, beta_);
        break;
    }
  }
  return sum;
}

void GroupedReturn::resolve_groups(Trial& t) const {
  for (int g = 0; g < group_count_; ++g) {
    const auto gg = static_cast<std::size_t>(g);
    const double rg = t.resultant[gg];
    t.inverse[gg] = rg > 0 ? 1 / rg : 0.0;
    const Group& gr = groups_[gg];
    if (gr.uniform) {
      t.reach[gg] = rg * gr.inverse_kappa;
      t.kappa[gg] = gr.kappa;
      continue;
    }
    // The group clips where its subgradient ζ_c = C_c t_c/(κ_c y) reaches |ζ| = 1.
    double reach2 = 0, weighted = 0;
    for_each_bit(gr.components, [&](int c) {
      const double a = gr.coefficient[c] * gr.coefficient[c] * t.force[c] * t.force[c];
      reach2 += a / (gr.component_kappa[c] * gr.component_kappa[c]);
      weighted += a * gr.component_kappa[c];
    });
    t.reach[gg] = std::sqrt(reach2);
    t.kappa[gg] = rg > 0 ? weighted * t.inverse[gg] * t.inverse[gg] : gr.kappa;
  }
  // r_g > 0 ⇔ r_g/κ_g > 0 (κ_g > 0).
  for (int i = 0; i < contribution_count_; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    t.positive[ii] = reaching_beyond(contributions_[ii].groups, t, 0.0);
  }
}

GroupedReturn::GroupSet GroupedReturn::reaching_beyond(unsigned candidates, const Trial& t,
                                                       double y) const {
  GroupSet set;
  for_each_bit(candidates, [&](int g) {
    const auto gg = static_cast<std::size_t>(g);
    if (!(t.reach[gg] > y)) return;  // clipped at y
    set.mask |= 1u << g;
    set.sum += t.resultant[gg];
    set.kappa += t.kappa[gg];
    set.first_clip = std::min(set.first_clip, t.reach[gg]);
  });
  return set;
}

GroupedReturn::GroupSet GroupedReturn::last_to_clip(unsigned candidates, const Trial& t) const {
  int last = -1;
  for_each_bit(candidates, [&](int g) {
    if (last < 0 || t.reach[static_cast<std::size_t>(g)] > t.reach[static_cast<std::size_t>(last)])
      last = g;
  });
  GroupSet set;
  if (last < 0) return set;
  const auto gg = static_cast<std::size_t>(last);
  set.mask = 1u << last;
  set.sum = t.resultant[gg];
  set.kappa = t.kappa[gg];
  set.first_clip = t.reach[gg];
  return set;
}

// A NORM group whose k_c C_c² = κ_c differ: F_c = t_c T/(T + κ_c y) from the flow rule, so its
// resultant T = |C∘F| solves h(T) = Σ_c a_c/(T + κ_c y)² = 1 (a_c = C_c² t_c²) for y below the
// clip, in the bracket [r − κ_max y, r − κ_min y] (at least 0). h is convex and decreasing, so
// Newton lands left of the root from anywhere in the bracket (clamped to its lower end) and then
// rises to it monotonically, quadratically. It starts from `guess` (T at the previous iterate of
// the joint Newton) where that is in the bracket. Returns T and −dT/dy =
// Σ a_c κ_c/s_c³ / Σ a_c/s_c³ (s_c = T + κ_c y).
[[gnu::noinline]] std::pair<double, double> GroupedReturn::norm_group_response(int group,
                                                                               const Trial& t,
                                                                               double y,
                                                                               double guess) const {
  const Group& gr = groups_[static_cast<std::size_t>(group)];
  double kappa_max = 0, kappa_min = std::numeric_limits<double>::infinity();
  for_each_bit(gr.components, [&](int c) {
    kappa_max = std::max(kappa_max, gr.component_kappa[c]);
    kappa_min = std::min(kappa_min, gr.component_kappa[c]);
  });
  const double r = t.resultant[static_cast<std::size_t>(group)];
  const double lower = std::max(0.0, r - kappa_max * y);
  double force = std::clamp(guess, lower, r - kappa_min * y);
  double slope_sum = 0, rate_sum = 0;  // Σ a_c/s_c³, Σ a_c κ_c/s_c³
  for (int k = 0; k < 60; ++k) {
    double h = 0;
    slope_sum = rate_sum = 0;
    for_each_bit(gr.components, [&](int c) {
      const double coefficient = gr.coefficient[c] * t.force[c];
      const double inv_s = 1 / (force + gr.component_kappa[c] * y);
      const double term = coefficient * coefficient * inv_s * inv_s;
      h += term;
      slope_sum += term * inv_s;
      rate_sum += term * inv_s * gr.component_kappa[c];
    });
    const double step = (h - 1) / (2 * slope_sum);  // −(h − 1)/h′, h′ = −2 Σ a_c/s_c³
    const double previous = force;
    force = std::max(lower, force + step);
    // Quadratic convergence: after a step of 1e-7 the error left is of order 1e-14, below what
    // the joint Newton resolves, so that step is the last (the rates are those before it).
    if (!(std::abs(force - previous) > 1e-7 * (force + y * kappa_max))) break;
  }
  return {force, rate_sum / slope_sum};
}

template <bool kAllUniform>
[[gnu::always_inline]] inline GroupedReturn::Response GroupedReturn::respond(int contribution,
                                                                             const Trial& t,
                                                                             double y,
                                                                             Iterate& it) const {
  const auto ii = static_cast<std::size_t>(contribution);
  Response out;
  if constexpr (kAllUniform) {  // linear pieces: T_g = r_g − κ_g y (filled in after the solve)
    const GroupSet& trial = t.positive[ii];
    if (y < trial.first_clip) return {trial.sum - trial.kappa * y, trial.kappa, trial.mask, false};
    GroupSet set = reaching_beyond(trial.mask, t, y);
    out.extended = !set.mask && t.positive[ii].mask;
    if (out.extended) set = last_to_clip(t.positive[ii].mask, t);
    out.force = set.sum - set.kappa * y;
    out.rate = set.kappa;
    out.mask = set.mask;
    return out;
  }
  for_each_bit(contributions_[ii].groups, [&](int g) {
    const auto gg = static_cast<std::size_t>(g);
    if (!(t.reach[gg] > y)) {  // clipped at y (or no flow)
      it.group_force[gg] = it.group_rate[gg] = 0;
      return;
    }
    const Group& gr = groups_[gg];
    const auto [force, rate] = gr.uniform ? std::pair{t.resultant[gg] - gr.kappa * y, gr.kappa}
                                          : norm_group_response(g, t, y, it.group_force[gg]);
    it.group_force[gg] = force;
    it.group_rate[gg] = rate;
    out.force += force;
    out.rate += rate;
    out.mask |= 1u << g;
  });
  if (out.mask || !t.positive[ii].mask) return out;
  // Past the last clip the iterate has overshot (the solution keeps E_i > 0 for β > 1): that
  // group's piece is continued linearly from its clip, with the slope it has there.
  const GroupSet last = last_to_clip(t.positive[ii].mask, t);
  const int g = std::countr_zero(last.mask);
  const auto gg = static_cast<std::size_t>(g);
  const Group& gr = groups_[gg];
  double rate = gr.kappa;
  if (!gr.uniform) {  // −dT/dy at T = 0: Σ a_c/κ_c² / Σ a_c/κ_c³
    double num = 0, den = 0;
    for_each_bit(gr.components, [&](int c) {
      const double a = gr.coefficient[c] * gr.coefficient[c] * t.force[c] * t.force[c];
      const double inv_k = 1 / gr.component_kappa[c];
      num += a * inv_k * inv_k;
      den += a * inv_k * inv_k * inv_k;
    });
    rate = num / den;
  }
  out.force = rate * (t.reach[gg] - y);
  out.rate = rate;
  out.mask = last.mask;
  out.extended = true;
  return out;
}

[[gnu::always_inline]] inline GroupedReturn::Share GroupedReturn::solve_share(
    int contribution, const Trial& t, double multiplier, const YieldSample& y) const {
  const auto ii = static_cast<std::size_t>(contribution);
  const Contribution& c = contributions_[ii];
  Share s;
  const double rf = c.scale * y.value;  // R_i F_y
  // Start with every positive group and drop those the solution clips. Taking a clipped group
  // as positive underestimates E_i(y), hence z and y, so a group found clipped at that z is
  // clipped at the true one too: the loop ends on the exact set, dropping at least one a pass.
  for (GroupSet set = t.positive[ii]; set.mask; set = reaching_beyond(set.mask, t, s.y)) {
    const double sum = set.sum, kappa = set.kappa;
    const double bk = multiplier * kappa * c.inverse_scale;  // Φ_i = rf z + bk z^(β−1) − sum
    // ∂Φ_i/∂z = rf + bk·(z^(β−1))′; each case forms its inverse with as few divisions as it can.
    switch (exponent_) {
      case Exponent::One:
        s.inv_a = 1 / rf;
        s.z = (sum - bk) * s.inv_a;
        s.zb1 = 1;
        s.dzb1_inv_a = 0;
        break;
      case Exponent::ThreeHalves: {
        // rf w² + bk w − sum = 0 with w = √z: w = 2 sum/(bk + ρ), ρ = √(bk² + 4 rf sum) (the form
        // without cancellation), and ∂Φ_i/∂z = (2 rf w + bk)/(2w) = ρ/(2w).
        const double rho = std::sqrt(bk * bk + 4 * rf * sum);
        const double w = 2 * sum / (bk + rho);
        const double inv_rho = 1 / rho;
        s.z = w * w;
        s.zb1 = w;
        s.inv_a = 2 * w * inv_rho;
        s.dzb1_inv_a = inv_rho;  // (0.5/w)·(2w/ρ)
        break;
      }
      case Exponent::Two:
        s.inv_a = 1 / (rf + bk);
        s.z = sum * s.inv_a;
        s.zb1 = s.z;
        s.dzb1_inv_a = s.inv_a;
        break;
      case Exponent::General: {
        // Φ_i is increasing in z on [0, sum/rf] with Φ_i(0) < 0 ≤ Φ_i(sum/rf): safeguarded Newton.
        double lo = 0, hi = sum / rf, z = hi;
        for (int k = 0; k < 100 && bk > 0; ++k) {
          const double phi = rf * z + bk * std::pow(z, beta_ - 1) - sum;
          if (std::abs(phi) <= 4 * kEpsilon * sum) break;
          (phi > 0 ? hi : lo) = z;
          const double next = z - phi / (rf + bk * (beta_ - 1) * std::pow(z, beta_ - 2));
          z = next > lo && next < hi ? next : 0.5 * (lo + hi);
        }
        const double dzb1 = (beta_ - 1) * std::pow(z, beta_ - 2);
        s.z = z;
        s.zb1 = dzb1 * z / (beta_ - 1);
        s.inv_a = 1 / (rf + bk * dzb1);
        s.dzb1_inv_a = dzb1 * s.inv_a;
        break;
      }
    }
    s.y = multiplier * s.zb1 * c.inverse_scale;
    if (s.y < set.first_clip) {
      s.active = set.mask;
      s.b = c.scale * y.slope * s.z + kappa * s.zb1 * c.inverse_scale;
      s.curvature = std::numeric_limits<double>::quiet_NaN();
      if (exponent_ == Exponent::ThreeHalves) {
        // With w = √z: w′ = −Φ_Δλ/ρ and w″ = −(Φ_ww w′² + 2 Φ_wΔλ w′)/ρ (F_y linear on its
        // segment), Φ_ww = 2 R F_y, Φ_wΔλ = 2 R h w + K/R; (w³)″ = 6 w w′² + 3 w² w″.
        const double w = s.zb1, inv_rho = s.dzb1_inv_a;
        const double w1 = -s.b * inv_rho;
        const double w2 =
            -(2 * rf * w1 * w1 + 2 * (2 * c.scale * y.slope * w + kappa * c.inverse_scale) * w1) *
            inv_rho;
        s.curvature = 6 * w * w1 * w1 + 3 * w * w * w2;
      }
      return s;
    }
  }
  return Share{0, 0, 1 / rf, 0, 0, 0, 0, 0};  // nothing positive: E_i = 0
}

[[gnu::always_inline]] inline void GroupedReturn::evaluate(const Trial& t, double multiplier,
                                                           const YieldSample& y,
                                                           Iterate& it) const {
  it.sum = 0;
  it.slope = 0;
  it.curvature = 0;
  for (int i = 0; i < contribution_count_; ++i) {
    const Share s = solve_share(i, t, multiplier, y);
    it.share[static_cast<std::size_t>(i)] = s;
    it.sum += s.z * s.zb1;
    it.slope += beta_ * s.zb1 * s.b * s.inv_a;
    it.curvature += s.curvature;
  }
}

// The first Δλ: the radial guess. Were every E_i to shrink by the same factor μ = P(F^tr)/F_y
// (F_y = F_y(ū_n) + h Δλ), each share would stay at ζ_i = E_i^tr/(R_i P(F^tr)) and so would its
// slope n_i = ζ_i^(β−1)/R_i; contribution i would need Δλ_i = s_i (1 − 1/μ)/(K_i n_i). Their
// mean weighted by ζ_i^β is (1 − 1/μ)·A with A = Σ_i ζ_i s_i R_i/K_i, which is linear in Δλ:
// Δλ = A (P^tr − F_y)/(P^tr + A h). Exact for a single contribution with linear hardening.
double GroupedReturn::radial_guess(const Trial& t, double share_sum, const YieldSample& y,
                                   double root) const {
  // P^tr/F_y = S^(1/β) = S/S^γ (root = S^γ).
  const double p_trial = y.value * share_sum / root;
  double a = 0;
  for (int i = 0; i < contribution_count_; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const GroupSet& g = t.positive[ii];
    if (g.kappa > 0) a += g.sum * g.sum / (p_trial * g.kappa);  // ζ_i s_i R_i/K_i
  }
  return a * (p_trial - y.value) / (p_trial + a * y.slope);
}

// The distance from the surface that the outer Newton drives to zero, g = (1 − S^(−γ))/γ
// (S − 1 for β = 1), and dg/dΔλ = −Q/S^(γ+1): far outside the surface z_i ∝ Δλ^(−1/(β−1)), so
// S^(−γ) is nearly linear in Δλ where S is not. Near S = 1, S^γ comes from its series in S − 1
// (third order) instead of a root.
GroupedReturn::Distance GroupedReturn::distance(const Iterate& it) const {
  const double psi = it.sum - 1;
  if (exponent_ == Exponent::One) return {psi, -it.slope, it.curvature};
  const double rise = std::abs(psi) < kNearSurface
                          ? psi * (1 + (gamma_ - 1) * psi * (0.5 + (gamma_ - 2) * psi / 6))
                          : (root_of_share_sum(it.sum) - 1) / gamma_;  // (S^γ − 1)/γ
  const double s_gamma = 1 + gamma_ * rise;
  // g′ = S^(−γ−1) S′ and g″ = S^(−γ−1) (S″ − (γ + 1) S′²/S), S′ = −Q; one division for
  // 1/S^γ, 1/S and S^(−γ−1).
  const double weight = 1 / (it.sum * s_gamma);
  return {rise * it.sum * weight, -it.slope * weight,
          weight * (it.curvature - (gamma_ + 1) * it.slope * it.slope * s_gamma * weight)};
}

CoupledReturn GroupedReturn::solve(const IsotropicHardeningLaw& yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent) const {
  CoupledReturn out;
  out.force = trial;
  Trial t;
  resolve_resultants(trial, t);
  const YieldSample y = yield.at(equivalent_old);
  if (!(y.value > 0)) {  // shares of a vanished yield size are not defined
    out.plastic = true;
    out.converged = false;
    return out;
  }
  // §6.4 step 1: at Δλ = 0 the shares are E_i^tr/(R_i F_y), so S > 1 ⇔ P(F^tr) > F_y. Most
  // updates end here, before any of the return's bookkeeping.
  const double share_sum = trial_share_sum(t, y.value);
  if (!(share_sum > 1)) return out;
  resolve_groups(t);
  out.plastic = true;
  Iterate it;
  double dl = 0;
  bool ok = (exponent_ == Exponent::ThreeHalves || (exponent_ == Exponent::Two && nonuniform_)) &&
            (nonuniform_ ? solve_jointly<false>(t, yield, equivalent_old, share_sum, it, dl)
                         : solve_jointly<true>(t, yield, equivalent_old, share_sum, it, dl));
  if (!ok && nonuniform_) {  // no closed-form shares: the general return takes over
    out.converged = false;
    return out;
  }
  if (!ok) {
    evaluate(t, 0, y, it);
    if (!(it.sum > 1)) {  // at round-off from the surface: the same test, exactly
      out.plastic = false;
      return out;
    }
    ok = solve_multiplier(t, yield, equivalent_old, it, dl);
  }
  if (!ok || !(it.slope > 0)) {
    out.converged = false;
    return out;
  }

  if (!nonuniform_) {  // every group uniform: T_g = r_g − κ_g y_i
    for (int g = 0; g < group_count_; ++g) {
      const auto gg = static_cast<std::size_t>(g);
      const Share& s = it.share[static_cast<std::size_t>(groups_[gg].contribution)];
      const bool active = (s.active >> g) & 1u;
      it.group_force[gg] = active ? std::max(0.0, t.resultant[gg] - groups_[gg].kappa * s.y) : 0;
      it.group_rate[gg] = active ? groups_[gg].kappa : 0;
    }
  }
  // The forces F_c = t_c T_g/(T_g + κ_c y_i) (zero where clipped; T_g + κ y_i = r_g where
  // uniform, a radial shrink).
  for (int g = 0; g < group_count_; ++g) {
    const auto gg = static_cast<std::size_t>(g);
    const Group& gr = groups_[gg];
    const Share& s = it.share[static_cast<std::size_t>(gr.contribution)];
    if (t.resultant[gg] <= 0) continue;  // no flow: an inactive Macaulay term or a zero resultant
    if (!((s.active >> g) & 1u)) {       // clipped
      for_each_bit(gr.components, [&](int k) { out.force[k] = 0; });
      continue;
    }
    const double force = it.group_force[gg];
    if (gr.uniform) {
      const double ratio = force * t.inverse[gg];
      for_each_bit(gr.components, [&](int k) { out.force[k] = trial[k] * ratio; });
      continue;
    }
    for_each_bit(gr.components, [&](int k) {
      out.force[k] = trial[k] * force / (force + gr.component_kappa[k] * s.y);
    });
  }
  out.multiplier = dl;
  if (want_tangent) tangent(trial, t, it, dl, out.tangent);
  return out;
}

// β = 1.5 and 2: Newton on Δλ and v_i = z_i^(β−1) together (√z_i, z_i), on
//   Φ_i = R_i F_y z_i − E_i(Δλ v_i/R_i) = 0,  Σ_i z_i^β = 1  (Σ v_i³, Σ v_i²),
// with the groups that stay positive taken at the iterate (E_i is piecewise smooth in y_i, so
// this is a semismooth Newton). With uniform groups E_i is linear in y_i and the equations are
// polynomials: a step takes one division per contribution and one for Δλ, where
// solve_multiplier takes a root and two divisions per contribution for each Δλ. It starts from the
// radial guess of Δλ with every share solved there (which saves one to two steps over the radial
// shares ζ_i) and stops when every Φ_i is within kTolerance of its Σ_g r_g and |S − 1| within
// β·kTolerance, the test of solve_multiplier. An iterate past the last clip of a contribution (the
// solution keeps E_i > 0 for β > 1) extends that group's linear piece. It gives up (false, `it`
// unchanged) where the plain Newton is not safe: a non-positive iterate, a vanished yield size, or
// no convergence in kJointIterations (an active set that cycles on a kink); solve_multiplier then
// takes over.
template <bool kAllUniform>
bool GroupedReturn::solve_jointly(const Trial& t, const IsotropicHardeningLaw& yield,
                                  double equivalent_old, double share_sum, Iterate& it,
                                  double& multiplier) const {
  constexpr int kJointIterations = 12;  // it takes 3–7 steps where it converges at all
  const bool root = exponent_ == Exponent::ThreeHalves;  // v = √z; otherwise β = 2 and v = z
  YieldSample y = yield.at(equivalent_old);
  double dl = radial_guess(t, share_sum, y, root_of_share_sum(share_sum));
  std::array<double, kMaxGroups> v{};
  if (dl > 0) {
    const YieldSample y0 = yield.at(equivalent_old + dl);
    for (int i = 0; i < contribution_count_; ++i) {
      v[static_cast<std::size_t>(i)] = solve_share(i, t, dl, y0).zb1;
    }
  }
  Iterate next;
  std::array<double, kMaxGroups> phi{};
  for (int iteration = 0; iteration < kJointIterations; ++iteration) {
    if (!(dl > 0)) return false;
    y = yield.at(equivalent_old + dl);
    if (!(y.value > 0)) return false;
    double psi = -1, weighted_residual = 0, slope = 0;  // S − 1, Σ q_i Φ_i, Q = Σ q_i b_i
    bool shares_converged = true;
    for (int i = 0; i < contribution_count_; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      Share& s = next.share[ii];
      if (!t.positive[ii].mask) {  // E_i^tr = 0: the share stays 0
        s = Share{0, 0, 0, 0, 0, 0, 0, 0};
        phi[ii] = 0;
        continue;
      }
      const Contribution& c = contributions_[ii];
      const double vi = v[ii];
      if (!(vi > 0)) return false;
      s.y = dl * vi * c.inverse_scale;
      const Response e = respond<kAllUniform>(i, t, s.y, next);
      const double rf = c.scale * y.value;
      const double kr = e.rate * c.inverse_scale;  // K_i/R_i
      s.z = root ? vi * vi : vi;
      phi[ii] = rf * s.z - e.force;
      const double inv_a = 1 / ((root ? 2 * rf * vi : rf) + dl * kr);  // 1/(∂Φ_i/∂v)
      s.zb1 = vi;
      s.inv_a = root ? 2 * vi * inv_a : inv_a;  // 1/(∂Φ_i/∂z) = (dz/dv)/(∂Φ_i/∂v)
      s.dzb1_inv_a = inv_a;
      s.b = c.scale * y.slope * s.z + kr * vi;  // ∂Φ_i/∂Δλ
      s.curvature = std::numeric_limits<double>::quiet_NaN();
      s.active = e.mask;
      const double q = (root ? 3 * s.z : 2 * vi) * inv_a;  // ∂(z_i^β)/∂v_i / (∂Φ_i/∂v)
      psi += s.z * vi;                                     // z^β = z·v
      weighted_residual += q * phi[ii];
      slope += q * s.b;
      // An extended piece is not a solution: that group's T_g would be negative.
      shares_converged =
          shares_converged && !e.extended && std::abs(phi[ii]) <= kTolerance * t.positive[ii].sum;
    }
    if (!(slope > 0)) return false;
    if (shares_converged && std::abs(psi) <= beta_ * kTolerance) {
      for (int i = 0; i < contribution_count_; ++i) {
        it.share[static_cast<std::size_t>(i)] = next.share[static_cast<std::size_t>(i)];
      }
      it.group_force = next.group_force;
      it.group_rate = next.group_rate;
      it.sum = psi + 1;
      it.slope = slope;  // Σ β z^(β−1) b/(∂Φ/∂z) = Σ (∂z^β/∂v) b/(∂Φ/∂v)
      multiplier = dl;
      return true;
    }
    // Σ (∂z_i^β/∂v_i) dv_i = −(S − 1) with dv_i = −(Φ_i + b_i dΔλ)/(∂Φ_i/∂v).
    const double step = (psi - weighted_residual) / slope;
    std::array<double, kMaxGroups> dv;
    for (int i = 0; i < contribution_count_; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      dv[ii] = -(phi[ii] + next.share[ii].b * step) * next.share[ii].dzb1_inv_a;
    }
    // Without the nested solve to fall back on (a non-uniform group), a step that would take
    // Δλ or a v_i below a tenth of its value (the solution has both positive) is shortened to
    // that; the direction stays Newton's. (It costs the uniform case a tenth of its time, and
    // there a non-positive iterate hands over to the nested solve instead.)
    double length = 1;
    if constexpr (!kAllUniform) {
      if (step < -0.9 * dl) length = -0.9 * dl / step;
      for (int i = 0; i < contribution_count_; ++i) {
        const auto ii = static_cast<std::size_t>(i);
        if (t.positive[ii].mask && length * dv[ii] < -0.9 * v[ii]) {
          length = -0.9 * v[ii] / dv[ii];
        }
      }
    }
    dl += length * step;
    for (int i = 0; i < contribution_count_; ++i) {
      v[static_cast<std::size_t>(i)] += length * dv[static_cast<std::size_t>(i)];
    }
  }
  return false;
}

// Δλ for the shares at Δλ = 0 in `it` (in: the shares at Δλ = 0; out: at the solution), by a
// safeguarded Newton on the distance from the surface with Halley's correction, each iterate
// solving every share equation for its Δλ (solve_share).
bool GroupedReturn::solve_multiplier(const Trial& t, const IsotropicHardeningLaw& yield,
                                     double equivalent_old, Iterate& it, double& multiplier) const {
  YieldSample y = yield.at(equivalent_old);
  double dl = 0, lo = 0, hi = std::numeric_limits<double>::infinity();
  double next = radial_guess(t, it.sum, y, root_of_share_sum(it.sum));
  Distance previous = distance(it);
  double previous_dl = 0;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    if (!(next > lo && next < hi)) {
      if (std::isfinite(hi)) {
        next = 0.5 * (lo + hi);
      } else {
        // No slope to follow (strong softening): expand from the Δλ that would clip a group.
        double reach = 0;
        for (int g = 0; g < group_count_; ++g) {
          const Group& gr = groups_[static_cast<std::size_t>(g)];
          reach = std::max(reach, contributions_[static_cast<std::size_t>(gr.contribution)].scale *
                                      t.reach[static_cast<std::size_t>(g)]);
        }
        next = dl > 0 ? 4 * dl : reach;
      }
    }
    dl = next;
    y = yield.at(equivalent_old + dl);
    if (!(y.value > 0)) return false;
    evaluate(t, dl, y, it);
    const double psi = it.sum - 1;
    multiplier = dl;
    if (std::abs(psi) <= beta_ * kTolerance) return true;
    (psi > 0 ? lo : hi) = dl;
    next = std::numeric_limits<double>::quiet_NaN();
    const Distance d = distance(it);
    if (!(d.slope < 0)) continue;
    // Halley's step: Newton's quadratic convergence has a large constant here (z_i is far from
    // linear in Δλ). g″ is exact for β = 1.5 (Share::curvature) and taken from the slopes at this
    // and the previous iterate otherwise; either saves about one evaluation per return. With
    // Newton's step −g/g′ and φ = 1 − g g″/(2 g′²), Halley's step −g/(g′ φ) = −2 g g′/(2 g′² − g
    // g″) takes one division. Outside φ ∈ [1/2, 2] (2 g′² φ outside [g′², 4 g′²]; a NaN curvature
    // included) the correction is not trusted and the step stays Newton's.
    const double curvature =
        std::isnan(d.curvature) ? (d.slope - previous.slope) / (dl - previous_dl) : d.curvature;
    const double slope2 = d.slope * d.slope;
    const double halley = 2 * slope2 - d.value * curvature;
    const double step = halley >= slope2 && halley <= 4 * slope2 ? -2 * d.value * d.slope / halley
                                                                 : -d.value / d.slope;
    previous = d;
    previous_dl = dl;
    if (std::abs(step) <= 4 * kEpsilon * dl && std::abs(psi) <= 1e3 * kTolerance) {
      return true;  // the remaining step is below the resolution of Δλ
    }
    next = dl + step;
  }
  return false;
}

// ∂F/∂u at the converged state, from F_c = t_c T_g/r_g (c in group g, t = F^tr = K(u − u^pl_n)):
//   dF_c = (T_g/r_g) dt_c + t_c d(T_g/r_g),  d(T_g/r_g) = κ_g y_i dr_g/r_g² − (κ_g/r_g) dy_i,
// dr_h = ∇r_h·dt with ∇r_h = C²∘t/r_h, and dy_i from linearising Φ_i = 0 and Σ z^β = 1:
//   dΔλ = Σ_j (q_j/Q) N_j·dt,  q_j = β z_j^(β−1)/a_j,  N_j = Σ_(h in j) ∇r_h,
//   dz_i = (N_i·dt − b_i dΔλ)/a_i,  dy_i = (z_i^(β−1) dΔλ + Δλ (z^(β−1))′ dz_i)/R_i
//        = Y_i dΔλ + X_i N_i·dt.
// So row c of ∂F/∂t is (T_g/r_g) e_c + t_c [κ_g y_i/r_g² ∇r_g − (κ_g/r_g)(Y_i W + X_i N_i)] with
// W = Σ_j (q_j/Q) N_j. A clipped group keeps F = 0 and does not enter E_i (zero rows and
// columns, as held kinks of closest_point_tangent); a group without flow keeps F = t.
// A non-uniform NORM group has F_c = t_c T_g/s_c with s_c = T_g + κ_c y_i, and from
// Σ_c a_c/s_c² = 1, dT_g = ∇T_g·dt − κ̄_g dy_i with ∇T_g = (C²∘t/s²)/Σ a/s³ and κ̄_g = −dT_g/dy;
// then dF_c = (T_g/s_c) dt_c + t_c κ_c/s_c² (y_i ∇T_g·dt − (T_g + κ̄_g y_i) dy_i), N_i sums
// ∇T_g, and with s_c = r_g, κ̄_g = κ_g this is the uniform row above. Each component is in one
// group at most, so N and W are vectors over the components, and the tangent is formed entry by
// entry, symmetric by construction.
void GroupedReturn::tangent(const Vector6& trial, const Trial& t, const Iterate& it, double dl,
                            Matrix6& out) const {
  std::array<double, kMaxGroups> x, yy, weight;  // X_i, Y_i, q_i/Q
  for (int i = 0; i < contribution_count_; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const Share& s = it.share[ii];
    const double inv_scale = contributions_[ii].inverse_scale;
    x[ii] = dl * s.dzb1_inv_a * inv_scale;
    yy[ii] = s.zb1 * inv_scale - x[ii] * s.b;
    weight[ii] = beta_ * s.zb1 * s.inv_a / it.slope;
  }
  // Per component c of group g and contribution i: N_c and W_c (∇T_g times K, ∂t/∂u = K), the
  // factors of dy_i and of ∇T_g·dt in row c, and the coefficient T_g/s_c k_c of e_c.
  Vector6 n = Vector6::Zero(), w = Vector6::Zero(), row = Vector6::Zero();
  Vector6 own = Vector6::Zero(), diagonal = Vector6::Zero();
  for (int g = 0; g < group_count_; ++g) {
    const auto gg = static_cast<std::size_t>(g);
    const Group& gr = groups_[gg];
    const auto i = static_cast<std::size_t>(gr.contribution);
    const Share& s = it.share[i];
    if (t.resultant[gg] <= 0) {
      for_each_bit(gr.components, [&](int c) { diagonal[c] = stiffness_[c]; });
      continue;
    }
    if (!((s.active >> g) & 1u)) continue;  // clipped
    const double force = it.group_force[gg];
    if (gr.uniform) {  // s_c = r_g, Σ a_c/s_c³ = 1/r_g, κ̄_g = κ_g
      const double inv_r = t.inverse[gg];
      const double kr = gr.kappa * inv_r;
      for_each_bit(gr.components, [&](int c) {
        n[c] = gr.coefficient[c] * gr.coefficient[c] * trial[c] * inv_r * stiffness_[c];
        w[c] = weight[i] * n[c];
        row[c] = -trial[c] * kr;
        own[c] = trial[c] * kr * s.y * inv_r;
        diagonal[c] = force * inv_r * stiffness_[c];
      });
      continue;
    }
    Vector6 inverse_s = Vector6::Zero();  // 1/s_c
    double scale = 0;                     // 1/Σ_c a_c/s_c³
    for_each_bit(gr.components, [&](int c) {
      const double a = gr.coefficient[c] * gr.coefficient[c] * trial[c] * trial[c];
      inverse_s[c] = 1 / (force + gr.component_kappa[c] * s.y);
      scale += a * inverse_s[c] * inverse_s[c] * inverse_s[c];
    });
    scale = 1 / scale;
    for_each_bit(gr.components, [&](int c) {
      const double inv_s = inverse_s[c];
      const double kappa_s2 = gr.component_kappa[c] * inv_s * inv_s;
      n[c] =
          gr.coefficient[c] * gr.coefficient[c] * trial[c] * inv_s * inv_s * scale * stiffness_[c];
      w[c] = weight[i] * n[c];
      row[c] = -trial[c] * kappa_s2 * (force + it.group_rate[gg] * s.y);
      own[c] = trial[c] * kappa_s2 * s.y;
      diagonal[c] = force * inv_s * stiffness_[c];
    });
  }
  // Row c: Y_i row_c W + X_i row_c N over the components of contribution i + own_c N over those
  // of group g, three outer products masked by the component pairs they couple.
  Vector6 row_y, row_x;
  for (int c = 0; c < 6; ++c) {
    const auto i = static_cast<std::size_t>(contribution_of_[c]);
    row_y[c] = row[c] * yy[i];
    row_x[c] = row[c] * x[i];
  }
  Matrix6 d = row_y * w.transpose();
  d += same_contribution_.cwiseProduct(row_x * n.transpose());
  d += same_group_.cwiseProduct(own * n.transpose());
  d.diagonal() += diagonal;
  // Symmetric in exact arithmetic (associated flow); symmetrising removes the round-off.
  out = 0.5 * (d + d.transpose());
}

}  // namespace clinch
