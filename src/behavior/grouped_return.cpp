#include "src/behavior/grouped_return.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

namespace clinch {
namespace {

constexpr int kMaxIterations = 60;  // Newton with bisection: far more than it ever needs
constexpr double kTolerance = 1e-12;  // on P/F_y − 1 (§6.4); |S − 1| ≤ β·kTolerance
// The Newton step is taken on S^(−γ) (γ = 1 − 1/β) rather than on S = Σ z_i^β: far outside the
// surface z_i ∝ Δλ^(−1/(β−1)), so S^(−γ) is nearly linear in Δλ where S is not. Within this
// distance of S = 1 the step uses the series of S^γ instead of the root.
constexpr double kNearSurface = 1e-2;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

template <typename F>
void for_each_bit(unsigned mask, F&& f) {
  while (mask) {
    f(std::countr_zero(mask));
    mask &= mask - 1;
  }
}

}  // namespace

// One contribution at a given Δλ: its share z = E_i/(R_i F_y), z^(β−1), the derivatives of its
// equation Φ_i = R_i F_y z + Δλ K_i z^(β−1)/R_i − Σ_g r_g, y_i = Δλ n_i, and which of its
// groups stay positive. Every field is written by solve_share.
struct GroupedReturn::Share {
  double z;
  double zb1;         // z^(β−1)
  double inv_a;       // 1/(∂Φ_i/∂z)
  double dzb1_inv_a;  // (z^(β−1))′/(∂Φ_i/∂z)
  double b;           // ∂Φ_i/∂Δλ
  double y;      // Δλ n_i
  unsigned active;  // bits of the groups (indices into groups_) with T_g > 0
};

struct GroupedReturn::Iterate {
  std::array<Share, kMaxGroups> share;
  double sum = 0;    // S = Σ z_i^β
  double slope = 0;  // Q = −dS/dΔλ = Σ β z_i^(β−1) (∂Φ_i/∂Δλ)/(∂Φ_i/∂z)
};

std::optional<GroupedReturn> GroupedReturn::create(const ConnectorPotential& potential,
                                                   const ElasticSpace& space) {
  std::vector<KinkGroup> groups;
  std::vector<double> scales;
  if (!potential.group_structure(groups, scales)) return std::nullopt;
  if (static_cast<int>(scales.size()) > kMaxGroups || static_cast<int>(groups.size()) > kMaxGroups) {
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
    r.contribution = g.contribution;
    r.coefficient = g.coefficient;
    bool first = true;
    for (int c = 0; c < 6; ++c) {
      if (!((g.components >> c) & 1u)) continue;
      const double kappa = k(c, c) * g.coefficient[c] * g.coefficient[c];
      if (first) {
        r.kappa = kappa;
        first = false;
      } else if (std::abs(kappa - r.kappa) > 1e-12 * r.kappa) {
        return std::nullopt;  // the flow would not be radial in this group
      }
    }
    if (!(r.kappa > 0)) return std::nullopt;
    out.groups_[static_cast<std::size_t>(out.group_count_++)] = r;
  }
  int next = 0;
  for (int i = 0; i < out.contribution_count_; ++i) {
    Contribution& c = out.contributions_[static_cast<std::size_t>(i)];
    c.scale = scales[static_cast<std::size_t>(i)];
    c.inverse_scale = 1 / c.scale;
    c.first = next;
    while (next < out.group_count_ && out.groups_[static_cast<std::size_t>(next)].contribution == i) {
      c.groups |= 1u << next++;
    }
  }
  out.beta_ = potential.exponent();
  out.gamma_ = 1 - 1 / out.beta_;
  out.exponent_ = out.beta_ == 1.0   ? Exponent::One
                  : out.beta_ == 1.5 ? Exponent::ThreeHalves
                  : out.beta_ == 2.0 ? Exponent::Two
                                     : Exponent::General;
  return out;
}

double GroupedReturn::root_of_share_sum(double s) const {  // S^γ, γ = 1 − 1/β
  switch (exponent_) {
    case Exponent::One: return 1;
    case Exponent::ThreeHalves: return std::cbrt(s);
    case Exponent::Two: return std::sqrt(s);
    case Exponent::General: break;
  }
  return std::pow(s, gamma_);
}

GroupedReturn::Share GroupedReturn::solve_share(const Contribution& c,
                                                const std::array<double, kMaxGroups>& resultant,
                                                double multiplier, const YieldSample& y) const {
  Share s;
  const double rf = c.scale * y.value;  // R_i F_y
  unsigned mask = 0;
  for_each_bit(c.groups, [&](int g) {
    if (resultant[static_cast<std::size_t>(g)] > 0) mask |= 1u << g;
  });
  // Start with every positive group and drop those the solution clips. Taking a clipped group
  // as positive underestimates E_i(y), hence z and y, so a group found clipped at that z is
  // clipped at the true one too: the loop ends on the exact set, dropping at least one a pass.
  while (mask) {
    double sum = 0, kappa = 0;
    for_each_bit(mask, [&](int g) {
      sum += resultant[static_cast<std::size_t>(g)];
      kappa += groups_[static_cast<std::size_t>(g)].kappa;
    });
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
    unsigned clipped = 0;
    for_each_bit(mask, [&](int g) {
      if (resultant[static_cast<std::size_t>(g)] <= groups_[static_cast<std::size_t>(g)].kappa * s.y) {
        clipped |= 1u << g;
      }
    });
    if (!clipped) {
      s.active = mask;
      s.b = c.scale * y.slope * s.z + kappa * s.zb1 * c.inverse_scale;
      return s;
    }
    mask &= ~clipped;
  }
  return Share{0, 0, 1 / rf, 0, 0, 0, 0};  // nothing positive: E_i = 0
}

void GroupedReturn::evaluate(const std::array<double, kMaxGroups>& resultant, double multiplier,
                             const YieldSample& y, Iterate& it) const {
  it.sum = 0;
  it.slope = 0;
  for (int i = 0; i < contribution_count_; ++i) {
    const Share s = solve_share(contributions_[static_cast<std::size_t>(i)], resultant, multiplier, y);
    it.share[static_cast<std::size_t>(i)] = s;
    it.sum += s.z * s.zb1;
    it.slope += beta_ * s.zb1 * s.b * s.inv_a;
  }
}

// The first Δλ: the radial guess. Were every share to shrink by the same factor
// λ = S₀^(1/β) = P(F^tr)/F_y, contribution i would need Δλ_i = s_i (1 − 1/λ)/(k̃_i ẑ_i^(β−1))
// (its equation at ẑ_i = z_i⁰/λ, k̃_i = K_i/R_i, F_y frozen); their mean weighted by ẑ_i^β is
// (1 − 1/λ) Σ_i s_i ẑ_i/k̃_i, exact for a single contribution of perfect plasticity.
double GroupedReturn::radial_guess(const std::array<double, kMaxGroups>& resultant,
                                   const Iterate& at_zero) const {
  const double lambda = at_zero.sum / root_of_share_sum(at_zero.sum);  // S^(1/β) = S/S^γ
  double sum = 0;
  for (int i = 0; i < contribution_count_; ++i) {
    const Contribution& c = contributions_[static_cast<std::size_t>(i)];
    const Share& s = at_zero.share[static_cast<std::size_t>(i)];
    double positive = 0, kappa = 0;
    for_each_bit(s.active, [&](int g) {
      positive += resultant[static_cast<std::size_t>(g)];
      kappa += groups_[static_cast<std::size_t>(g)].kappa;
    });
    if (kappa > 0) sum += positive * (s.z / lambda) * c.scale / kappa;
  }
  return (1 - 1 / lambda) * sum;
}

CoupledReturn GroupedReturn::solve(const IsotropicHardeningLaw& yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent) const {
  CoupledReturn out;
  out.force = trial;
  // Trial resultants r_g (a Macaulay group: its positive part; a negative one has no flow).
  std::array<double, kMaxGroups> r;
  for (int g = 0; g < group_count_; ++g) {
    const Group& gr = groups_[static_cast<std::size_t>(g)];
    double v = 0;
    for_each_bit(gr.components, [&](int c) {
      const double x = gr.coefficient[c] * trial[c];
      v = gr.macauley ? std::max(0.0, x) : v + x * x;
    });
    r[static_cast<std::size_t>(g)] = gr.macauley ? v : std::sqrt(v);
  }
  YieldSample y = yield.at(equivalent_old);
  if (!(y.value > 0)) {  // shares of a vanished yield size are not defined
    out.plastic = true;
    out.converged = false;
    return out;
  }
  Iterate it;
  evaluate(r, 0, y, it);
  // §6.4 step 1: at Δλ = 0 the shares are E_i^tr/(R_i F_y), so S > 1 ⇔ P(F^tr) > F_y.
  if (!(it.sum > 1)) return out;
  out.plastic = true;

  double dl = 0, lo = 0, hi = std::numeric_limits<double>::infinity();
  double next = radial_guess(r, it);
  bool ok = false;
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
                                      r[static_cast<std::size_t>(g)] / gr.kappa);
        }
        next = dl > 0 ? 4 * dl : reach;
      }
    }
    dl = next;
    y = yield.at(equivalent_old + dl);
    if (!(y.value > 0)) break;
    evaluate(r, dl, y, it);
    const double psi = it.sum - 1;
    if (std::abs(psi) <= beta_ * kTolerance) {
      ok = true;
      break;
    }
    (psi > 0 ? lo : hi) = dl;
    next = std::numeric_limits<double>::quiet_NaN();
    if (!(it.slope > 0)) continue;
    // Newton on χ = 1 − S^(−γ): Δλ += S (S^γ − 1)/(γ Q). Near the surface S^γ − 1 is its series
    // in ψ = S − 1 (third order), so the root is taken only far from it.
    double rise = 0;  // (S^γ − 1)/γ
    if (exponent_ == Exponent::One) {
      rise = psi;
    } else if (std::abs(psi) < kNearSurface) {
      rise = psi * (1 + (gamma_ - 1) * psi * (0.5 + (gamma_ - 2) * psi / 6));
    } else {
      rise = (root_of_share_sum(it.sum) - 1) / gamma_;
    }
    const double step = it.sum * rise / it.slope;
    if (std::abs(step) <= 4 * kEpsilon * dl && std::abs(psi) <= 1e3 * kTolerance) {
      ok = true;  // the remaining step is below the resolution of Δλ
      break;
    }
    next = dl + step;
  }
  if (!ok || !(it.slope > 0)) {
    out.converged = false;
    return out;
  }

  // The forces: every group shrunk radially to T_g (zero where clipped).
  for (int i = 0; i < contribution_count_; ++i) {
    const Contribution& c = contributions_[static_cast<std::size_t>(i)];
    const Share& s = it.share[static_cast<std::size_t>(i)];
    for_each_bit(c.groups, [&](int g) {
      const Group& gr = groups_[static_cast<std::size_t>(g)];
      const double rg = r[static_cast<std::size_t>(g)];
      if (rg <= 0) return;  // no flow: an inactive Macaulay term or a zero resultant
      const double ratio = (s.active >> g) & 1u ? (rg - gr.kappa * s.y) / rg : 0.0;
      for_each_bit(gr.components, [&](int k) { out.force[k] = trial[k] * ratio; });
    });
  }
  out.multiplier = dl;
  if (want_tangent) tangent(trial, r, it, dl, out.tangent);
  return out;
}

// ∂F/∂u at the converged state, from F_c = t_c T_g/r_g (c in group g, t = F^tr = K(u − u^pl_n)):
//   dF_c = (T_g/r_g) dt_c + t_c d(T_g/r_g),  d(T_g/r_g) = κ_g y_i dr_g/r_g² − (κ_g/r_g) dy_i,
// dr_h = ∇r_h·dt with ∇r_h = C²∘t/r_h, and dy_i from linearising Φ_i = 0 and Σ z^β = 1:
//   dΔλ = Σ_h q_i(h) dr_h / Q,  q_i = β z_i^(β−1)/a_i,  dz_i = (Σ_(h in i) dr_h − b_i dΔλ)/a_i,
//   dy_i = (z_i^(β−1) dΔλ + Δλ (z^(β−1))' dz_i)/R_i = Y_i dΔλ + X_i Σ_(h in i) dr_h.
// A clipped group keeps F = 0 and does not enter E_i (zero rows and columns, as held kinks of
// closest_point_tangent); a group without flow keeps F = t (the elastic row).
void GroupedReturn::tangent(const Vector6& trial, const std::array<double, kMaxGroups>& r,
                            const Iterate& it, double dl, Matrix6& out) const {
  std::array<double, kMaxGroups> x, yy, u;  // X_i, Y_i per contribution; ∂Δλ/∂r_h per group
  for (int i = 0; i < contribution_count_; ++i) {
    const Share& s = it.share[static_cast<std::size_t>(i)];
    const double inv_scale = contributions_[static_cast<std::size_t>(i)].inverse_scale;
    const double xi = dl * s.dzb1_inv_a * inv_scale;
    x[static_cast<std::size_t>(i)] = xi;
    yy[static_cast<std::size_t>(i)] = s.zb1 * inv_scale - xi * s.b;
    const double ui = beta_ * s.zb1 * s.inv_a / it.slope;
    for_each_bit(s.active, [&](int h) { u[static_cast<std::size_t>(h)] = ui; });
  }
  // ∂F/∂t, then ∂F/∂u = ∂F/∂t · K.
  out.setZero();
  for (int g = 0; g < group_count_; ++g) {
    const Group& gg = groups_[static_cast<std::size_t>(g)];
    const auto i = static_cast<std::size_t>(gg.contribution);
    const Share& s = it.share[i];
    const double rg = r[static_cast<std::size_t>(g)];
    if (rg <= 0) {
      for_each_bit(gg.components, [&](int c) { out(c, c) = 1; });
      continue;
    }
    if (!((s.active >> g) & 1u)) continue;  // clipped
    const double ratio = (rg - gg.kappa * s.y) / rg;
    for_each_bit(gg.components, [&](int c) { out(c, c) = ratio; });
    const double kr = gg.kappa / rg;
    for (int j = 0; j < contribution_count_; ++j) {
      for_each_bit(it.share[static_cast<std::size_t>(j)].active, [&](int h) {
        const Group& gh = groups_[static_cast<std::size_t>(h)];
        const double rh = r[static_cast<std::size_t>(h)];
        double m = -kr * (yy[i] * u[static_cast<std::size_t>(h)] + (i == static_cast<std::size_t>(j) ? x[i] : 0.0));
        if (g == h) m += kr * s.y / rg;
        const double mr = m / rh;
        for_each_bit(gg.components, [&](int c) {
          const double tm = trial[c] * mr;
          for_each_bit(gh.components, [&](int e) {
            out(c, e) += tm * gh.coefficient[e] * gh.coefficient[e] * trial[e];
          });
        });
      });
    }
  }
  for (int e = 0; e < 6; ++e) out.col(e) *= stiffness_[e];
  // Symmetric in exact arithmetic (associated flow); symmetrising removes the round-off.
  for (int c = 0; c < 6; ++c) {
    for (int e = c + 1; e < 6; ++e) out(c, e) = out(e, c) = 0.5 * (out(c, e) + out(e, c));
  }
}

}  // namespace clinch
