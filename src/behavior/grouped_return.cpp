#include "src/behavior/grouped_return.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "src/behavior/coupled_return_mapping.hpp"

namespace clinch {
namespace {

constexpr int kMaxContributions = 6;  // one per component at the most
constexpr int kMaxIterations = 40;
constexpr double kTolerance = 1e-13;  // relative, below the 1e-12 of §6.4

}  // namespace

std::optional<GroupedReturn> GroupedReturn::create(const ConnectorPotential& potential,
                                                   const ElasticSpace& space) {
  std::vector<KinkGroup> groups;
  GroupedReturn out;
  if (!potential.group_structure(groups, out.scales_)) return std::nullopt;
  if (static_cast<int>(out.scales_.size()) > kMaxContributions) return std::nullopt;
  const Matrix6& k = space.stiffness;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      if (i != j && k(i, j) != 0) return std::nullopt;  // K must be diagonal
    }
  }
  for (std::size_t n = 0; n < groups.size(); ++n) {
    const KinkGroup& g = groups[n];
    Group r;
    r.index = n;
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
    out.groups_.push_back(r);
  }
  out.beta_ = FixedPower(potential.exponent());
  return out;
}

CoupledReturn GroupedReturn::solve(const ElasticSpace& space, const ConnectorPotential& potential,
                                   const IsotropicHardeningLaw& yield, const Vector6& trial,
                                   double equivalent_old, bool want_tangent) const {
  CoupledReturn out;
  out.force = trial;
  const int m = static_cast<int>(scales_.size());
  // Trial resultants r_g (a Macaulay group: its positive part; a negative one has no flow).
  std::array<double, 6> r{};
  std::array<double, kMaxContributions> e_trial{};
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const Group& gr = groups_[g];
    double v = 0;
    for (int c = 0; c < 6; ++c) {
      if (!((gr.components >> c) & 1u)) continue;
      const double y = gr.coefficient[c] * trial[c];
      v = gr.macauley ? std::max(0.0, y) : v + y * y;
    }
    r[g] = gr.macauley ? v : std::sqrt(v);
    e_trial[static_cast<std::size_t>(gr.contribution)] += r[g];
  }
  auto potential_of = [&](const std::array<double, kMaxContributions>& e) {
    double s = 0;
    for (int i = 0; i < m; ++i) {
      s += beta_.power(e[static_cast<std::size_t>(i)] / scales_[static_cast<std::size_t>(i)]);
    }
    return beta_.root(s);
  };
  const double yield_old = yield.at(equivalent_old).value;
  if (!(potential_of(e_trial) - yield_old > 0)) return out;  // §6.4 step 1: elastic
  out.plastic = true;

  // Newton on x = (E_1 … E_m, Δλ): ρ_i = E_i − Σ_g ⟨r_g − κ_g Δλ n_i⟩, ρ_0 = P(E) − F_y(ū_n + Δλ).
  // With K_i = Σ κ_g over the active groups of contribution i and ∂n_i/∂E_j =
  // ((β − 1)/P)[δ_ij n_i P/E_i − n_i n_j] (§2.4; the diagonal term is taken as 0 at E_i = 0, §2.5),
  // the E-block of the Jacobian is Λ − a nᵀ (Λ_ii = 1 + K_i Δλ (β − 1) n_i/E_i,
  // a_i = K_i Δλ (β − 1) n_i/P), so each step is a Sherman–Morrison solve in O(m).
  std::array<double, kMaxContributions> e = e_trial;
  double dl = 0;
  bool ok = false;
  std::array<double, kMaxContributions> n{};
  double scale = 0;
  for (int i = 0; i < m; ++i) scale = std::max(scale, e_trial[static_cast<std::size_t>(i)]);
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double p = potential_of(e);
    if (!(p > 0)) break;
    for (int i = 0; i < m; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      // n_i = (P_i/P)^(β−1)/R_i (§2.4), as (P_i/P)^β/(P_i/P).
      const double q = e[ii] / (scales_[ii] * p);
      n[ii] = (q > 0 ? beta_.power(q) / q : (beta_.is_one() ? 1.0 : 0.0)) / scales_[ii];
    }
    const YieldSample y = yield.at(equivalent_old + dl);
    std::array<double, kMaxContributions> rho = e, stiff{};
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      const auto i = static_cast<std::size_t>(groups_[g].contribution);
      const double t = r[g] - groups_[g].kappa * dl * n[i];
      if (t > 0) {
        rho[i] -= t;
        stiff[i] += groups_[g].kappa;
      }
    }
    const double rho0 = p - y.value;
    double worst = 0;
    for (int i = 0; i < m; ++i) worst = std::max(worst, std::abs(rho[static_cast<std::size_t>(i)]));
    if (worst <= kTolerance * scale && std::abs(rho0) <= kTolerance * y.value) {
      ok = true;
      break;
    }
    std::array<double, kMaxContributions> inv_lambda{}, a{}, b{};
    double n_li_a = 0;  // nᵀΛ⁻¹a
    for (int i = 0; i < m; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      const double c = stiff[ii] * dl * (beta_.exponent() - 1.0);
      inv_lambda[ii] = 1.0 / (1.0 + (e[ii] > 0 ? c * n[ii] / e[ii] : 0.0));
      a[ii] = c * n[ii] / p;
      b[ii] = stiff[ii] * n[ii];  // ∂ρ_i/∂Δλ
      n_li_a += n[ii] * inv_lambda[ii] * a[ii];
    }
    const double sm = 1.0 - n_li_a;
    if (!(std::abs(sm) > 0)) break;
    // A⁻¹v = Λ⁻¹v + Λ⁻¹a (nᵀΛ⁻¹v)/(1 − nᵀΛ⁻¹a).
    auto solve_a = [&](const std::array<double, kMaxContributions>& v) {
      std::array<double, kMaxContributions> x{};
      double nt = 0;
      for (int i = 0; i < m; ++i) {
        const auto ii = static_cast<std::size_t>(i);
        x[ii] = inv_lambda[ii] * v[ii];
        nt += n[ii] * x[ii];
      }
      for (int i = 0; i < m; ++i) {
        const auto ii = static_cast<std::size_t>(i);
        x[ii] += inv_lambda[ii] * a[ii] * nt / sm;
      }
      return x;
    };
    const std::array<double, kMaxContributions> a_rho = solve_a(rho), a_b = solve_a(b);
    double n_a_rho = 0, n_a_b = 0;
    for (int i = 0; i < m; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      n_a_rho += n[ii] * a_rho[ii];
      n_a_b += n[ii] * a_b[ii];
    }
    const double denominator = n_a_b + y.slope;
    if (!(denominator > 0)) break;
    const double d_dl = (rho0 - n_a_rho) / denominator;
    // A full step may drive a contribution through zero, where its slope n_i vanishes and the
    // iteration would lose it: the step is shortened so that every E_i keeps at least a tenth
    // of its value (a contribution that truly vanishes is approached geometrically).
    double theta = 1.0;
    std::array<double, kMaxContributions> de{};
    for (int i = 0; i < m; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      de[ii] = -a_rho[ii] - a_b[ii] * d_dl;
      if (e[ii] + de[ii] < 0.1 * e[ii]) theta = std::min(theta, 0.9 * e[ii] / -de[ii]);
    }
    for (int i = 0; i < m; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      e[ii] = std::min(e[ii] + theta * de[ii], e_trial[ii]);
    }
    dl = std::max(0.0, dl + theta * d_dl);
  }
  if (!ok) {
    out.converged = false;
    return out;
  }

  // The forces: every group shrunk radially to T_g (held at zero where clipped).
  ComponentMask held = 0;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const Group& gr = groups_[g];
    const double t = std::max(0.0, r[g] - gr.kappa * dl * n[static_cast<std::size_t>(gr.contribution)]);
    if (r[g] <= 0) continue;  // no flow: an inactive Macaulay term or a zero resultant
    const double ratio = t / r[g];
    if (t == 0) held = static_cast<ComponentMask>(held | gr.components);
    for (int c = 0; c < 6; ++c) {
      if ((gr.components >> c) & 1u) out.force[c] = trial[c] * ratio;
    }
  }
  out.multiplier = dl;
  if (want_tangent) {
    PotentialValue pv;
    potential.evaluate(out.force, pv, true);
    out.tangent = closest_point_tangent(space, pv.gradient, pv.hessian, dl,
                                        yield.at(equivalent_old + dl).slope, held);
  }
  return out;
}

}  // namespace clinch
