// Evaluation of a connector potential (derived-components-and-potentials.md §2.3–§2.5).
//
// SUM is evaluated through the base S = Σ s_i u_i^α_i with u_i = P_i/λ and P = λ·F(S),
// F(S) = S^(1/β). λ = max_i |X_i| when every α_i = β (P is then homogeneous of degree 1 in the
// P_i, so scaling keeps u_i ≤ 1 and the powers far from overflow and underflow), λ = 1 otherwise.
// With ĝ_i = s_i α_i u_i^(α_i−1) H_i'/R_i and d̂_i = s_i α_i (α_i−1) u_i^(α_i−2) (H_i'/R_i)², the
// formulas of §2.4 become
//   ∂P/∂E_i        = F'·ĝ_i
//   ∂²P/∂E_i∂E_j  = (F''/λ)·ĝ_i ĝ_j + δ_ij (F'/λ)·d̂_i
// with F' = F/(β S) and F'' = (1/β − 1)·F'/S. For α_i = β these are exactly the n_i and Hessian
// of the "α_i = β" formulas of §2.4, and for general α_i those of the general formulas. The
// Hessian with respect to c is then a rank-one term over the components of §2.8, one small
// outer product per contribution over the components of its E_i, and the NORM-term curvature
// F'·ĝ_i·∇²E_i of the derived components (chain rule of §2.4), so no full 6×6 product is formed.
#include "src/behavior/potential/connector_potential.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace clinch {
namespace {

// §2.5: "zero" uses the relative threshold of §1.4 with m = the largest |X_i| of the potential.
constexpr double kZeroTolerance = 1e-12;
// Potentials with more contributions than this evaluate with a heap scratch buffer; every
// potential of a real deck (one line per component or derived component) fits inline.
constexpr int kInlineContributions = 8;

struct Scratch {
  double x;  // X_i
  double g;  // ĝ_i (0: the contribution adds no derivative)
  double d;  // d̂_i
  Vector6 grad;  // ∇E_i of a derived contribution
};

// H_i and H_i' with the conventions of §2.5: H' = 0 at X = 0 for ABS and MACAULEY, and "zero"
// relative to `zero`. Returns H'; `p` receives P_i (0 below the threshold).
inline double apply_function(PotentialFunction h, double x, double zero, double& p) {
  switch (h) {
    case PotentialFunction::Abs:
      if (std::fabs(x) > zero) {
        p = std::fabs(x);
        return x > 0 ? 1.0 : -1.0;
      }
      break;
    case PotentialFunction::Macauley:
      if (x > zero) {
        p = x;
        return 1.0;
      }
      break;
    case PotentialFunction::None:
      // Smooth everywhere (α = β = 1 by §2.3), so no threshold applies.
      p = x;
      return 1.0;
  }
  p = 0;
  return 0;
}

ComponentMask mask_slots(ComponentMask mask, std::array<std::int8_t, 6>& slots, int& count) {
  count = 0;
  for (int k = 0; k < 6; ++k) {
    if (mask & (1u << k)) slots[static_cast<std::size_t>(count++)] = static_cast<std::int8_t>(k);
  }
  return mask;
}

}  // namespace

ConnectorPotential ConnectorPotential::compile(const ConnectorBehavior& behavior,
                                               const Potential& potential) {
  ConnectorPotential out;
  out.op_ = potential.op;
  out.beta_ = potential.exponent;
  if (!(out.beta_ > 0)) throw std::invalid_argument("potential exponent must be positive");
  out.inverse_beta_ = 1.0 / out.beta_;
  out.beta_power_ = FixedPower(out.beta_);
  out.inverse_beta_is_integer_ = out.inverse_beta_ == std::round(out.inverse_beta_);
  out.type_ = potential.type;

  std::vector<std::string> keys;  // derived_[j] is the derived component named keys[j]
  for (const PotentialContribution& c : potential.contributions) {
    Contribution k;
    ComponentMask mask = 0;
    if (c.derived) {
      std::size_t j = 0;
      while (j < keys.size() && keys[j] != c.derived_name.key) ++j;
      if (j == keys.size()) {
        out.derived_.push_back(DerivedComponent::compile(behavior, c.derived_name.key));
        keys.push_back(c.derived_name.key);
      }
      k.derived = static_cast<int>(j);
      mask = out.derived_[j].components();
    } else {
      if (c.component < 1 || c.component > 6) {
        throw std::invalid_argument("potential contribution on component " +
                                    std::to_string(c.component));
      }
      k.slot = c.component - 1;
      mask = static_cast<ComponentMask>(1u << k.slot);
    }
    if (c.scale == 0) throw std::invalid_argument("potential contribution with R = 0");
    k.scale = c.scale;
    k.inverse_scale = 1.0 / c.scale;
    k.alpha = c.alpha;
    k.shift = c.shift;
    k.sign = c.sign < 0 ? -1.0 : 1.0;
    k.function = c.function;
    k.power = FixedPower(k.alpha);
    mask_slots(mask, k.slots, k.slot_count);
    if (k.alpha != out.beta_) out.homogeneous_ = false;
    out.components_ = static_cast<ComponentMask>(out.components_ | mask);
    out.contributions_.push_back(k);
  }
  mask_slots(out.components_, out.slots_, out.slot_count_);
  out.collect_kink_groups();
  return out;
}

void ConnectorPotential::append_term_groups(const DerivedComponent::Term& t, int contribution,
                                            std::vector<KinkGroup>& out) {
  if (t.op == DerivedOperator::Sum) return;  // linear: no kink
  KinkGroup g;
  g.contribution = contribution;
  g.macauley = t.op == DerivedOperator::MacauleySum;
  for (int j = 0; j < t.count; ++j) {
    g.components = static_cast<ComponentMask>(g.components | (1u << t.slot[j]));
    g.coefficient[t.slot[j]] = t.sign * t.coefficient[j];
    // A MACAULEY SUM term brackets each product (§1.3): one group per component.
    if (g.macauley) {
      out.push_back(g);
      g.components = 0;
      g.coefficient.setZero();
    }
  }
  if (!g.macauley) out.push_back(g);
}

bool ConnectorPotential::group_structure(std::vector<KinkGroup>& groups,
                                         std::vector<double>& scales) const {
  groups.clear();
  scales.clear();
  if (op_ != PotentialOperator::Sum || !homogeneous_ || beta_ < 1) return false;
  ComponentMask listed = 0;
  auto add = [&](const KinkGroup& g) {
    if (listed & g.components) return false;
    listed = static_cast<ComponentMask>(listed | g.components);
    groups.push_back(g);
    return true;
  };
  for (int i = 0; i < contribution_count(); ++i) {
    const Contribution& k = contributions_[static_cast<std::size_t>(i)];
    if (k.shift != 0 || k.sign < 0 || k.function == PotentialFunction::None) return false;
    scales.push_back(k.scale);
    if (k.slot >= 0) {
      KinkGroup g;
      g.contribution = i;
      g.macauley = k.function == PotentialFunction::Macauley;
      g.components = static_cast<ComponentMask>(1u << k.slot);
      g.coefficient[k.slot] = 1.0;
      if (!add(g)) return false;
      continue;
    }
    std::vector<KinkGroup> term_groups;
    for (const DerivedComponent::Term& t : derived_[static_cast<std::size_t>(k.derived)].terms_) {
      if (t.op == DerivedOperator::Sum || t.sign < 0) return false;
      append_term_groups(t, i, term_groups);
    }
    for (const KinkGroup& g : term_groups) {
      if (!add(g)) return false;
    }
  }
  return true;
}

void ConnectorPotential::collect_kink_groups() {
  if (op_ != PotentialOperator::Sum) return;
  // How many contributions or terms list each component: a group is kept only when each of its
  // components is listed once in the whole potential.
  std::array<int, 6> listed{};
  std::vector<KinkGroup> groups;
  for (int i = 0; i < contribution_count(); ++i) {
    const Contribution& k = contributions_[static_cast<std::size_t>(i)];
    if (k.slot >= 0) {
      ++listed[static_cast<std::size_t>(k.slot)];
      continue;
    }
    for (const DerivedComponent::Term& t : derived_[static_cast<std::size_t>(k.derived)].terms_) {
      for (int j = 0; j < t.count; ++j) ++listed[static_cast<std::size_t>(t.slot[j])];
      if (i < PotentialValue::kSlopedContributions) append_term_groups(t, i, groups);
    }
  }
  for (const KinkGroup& g : groups) {
    bool alone = true;
    for (int a = 0; a < 6; ++a) {
      if ((g.components >> a) & 1u) alone = alone && listed[static_cast<std::size_t>(a)] == 1;
    }
    if (alone) kink_groups_.push_back(g);
  }
}

void ConnectorPotential::evaluate(const Vector6& c, PotentialValue& out, bool hessian) const {
  out.active = -1;
  out.negative_base = false;
  const Want want = hessian ? Want::Hessian : Want::Gradient;
  out.value = op_ == PotentialOperator::Sum ? evaluate_sum(c, &out, want)
                                            : evaluate_max(c, &out, want);
}

double ConnectorPotential::value(const Vector6& c) const {
  return op_ == PotentialOperator::Sum ? evaluate_sum(c, nullptr, Want::Value)
                                       : evaluate_max(c, nullptr, Want::Value);
}

double ConnectorPotential::evaluate_sum(const Vector6& c, PotentialValue* out, Want want) const {
  const int n = contribution_count();
  std::array<Scratch, kInlineContributions> inline_scratch;
  std::vector<Scratch> heap_scratch;
  Scratch* w = inline_scratch.data();
  if (n > kInlineContributions) {
    heap_scratch.resize(static_cast<std::size_t>(n));
    w = heap_scratch.data();
  }
  const bool derivatives = want != Want::Value;

  // X_i and m = max |X_i| first: the zero threshold of every contribution depends on m (§2.5).
  double m = 0;
  for (int i = 0; i < n; ++i) {
    const Contribution& k = contributions_[static_cast<std::size_t>(i)];
    const double e = k.slot >= 0 ? c[k.slot]
                                 : derived_[static_cast<std::size_t>(k.derived)].evaluate_into(
                                       c, derivatives ? &w[i].grad : nullptr, nullptr, 0.0);
    w[i].x = (e - k.shift) / k.scale;
    m = std::max(m, std::fabs(w[i].x));
  }
  const double zero = kZeroTolerance * m;
  const double lambda = homogeneous_ && m > 0 ? m : 1.0;
  const double inverse_lambda = 1.0 / lambda;

  double s = 0, s_abs = 0;
  Vector6 g_sum = Vector6::Zero();  // Ĝ = Σ ĝ_i ∇E_i
  for (int i = 0; i < n; ++i) {
    const Contribution& k = contributions_[static_cast<std::size_t>(i)];
    Scratch& wi = w[i];
    double p = 0;
    const double h = apply_function(k.function, wi.x, zero, p);
    wi.g = 0;
    wi.d = 0;
    // H' = 0 means P_i = 0 (ABS, MACAULEY): no value, n_i = 0, and the diagonal Hessian term,
    // unbounded for 1 < β < 2, is taken as 0 (§2.5 table).
    if (h == 0) continue;
    const double u = p * inverse_lambda;
    const double ua = k.power.power(u);
    s += k.sign * ua;
    s_abs += std::fabs(ua);
    if (!derivatives) continue;
    const double hr = h * k.inverse_scale;
    if (k.power.is_one()) {
      wi.g = k.sign * hr;
    } else {
      const double ua_over_u = ua / u;  // u > 0: above the zero threshold
      wi.g = k.sign * k.alpha * ua_over_u * hr;
      wi.d = k.sign * k.alpha * (k.alpha - 1.0) * (ua_over_u / u) * hr * hr;
    }
    if (k.slot >= 0) {
      g_sum[k.slot] += wi.g;
    } else {
      for (int a = 0; a < k.slot_count; ++a) {
        const int sa = k.slots[static_cast<std::size_t>(a)];
        g_sum[sa] += wi.g * wi.grad[sa];
      }
    }
  }

  double f = s, f1 = 1.0, f2 = 0.0;  // F(S), F'(S), F''(S)
  if (!beta_power_.is_one()) {
    // P = 0 (all contributions zero) gives value, gradient and Hessian 0 (§2.5). A base that
    // cancels to zero through negative signs (damage potentials only) is treated the same way:
    // F' is unbounded there for β > 1, and 0 keeps the outputs finite. This is a clinch choice.
    if (s_abs == 0 || std::fabs(s) <= kZeroTolerance * s_abs) {
      if (out) {
        out->gradient.setZero();
        out->slope.fill(0.0);
        if (want == Want::Hessian) out->hessian.setZero();
      }
      return 0;
    }
    // S^(1/β) for S > 0 without std::pow for β = 1.5, 2, 3, 4 (§5).
    auto root = [this](double v) { return beta_power_.root(v); };
    if (s > 0) {
      f = root(s);
    } else if (inverse_beta_is_integer_) {
      f = std::pow(s, inverse_beta_);  // real for an integer 1/β (§2.3)
    } else {
      // Odd extension sgn(S)·|S|^(1/β) (§2.3); F' = F/(βS) and F'' below hold for it unchanged.
      f = -root(-s);
      if (out) out->negative_base = true;
    }
    if (out) {
      f1 = inverse_beta_ * f / s;
      f2 = (inverse_beta_ - 1.0) * f1 / s;
    }
  }
  const double value = lambda * f;
  if (!out) return value;

  out->gradient = f1 * g_sum;
  for (int i = 0; i < std::min(n, PotentialValue::kSlopedContributions); ++i) {
    out->slope[static_cast<std::size_t>(i)] = f1 * w[i].g;
  }
  if (want != Want::Hessian) return value;

  Matrix6& hess = out->hessian;
  hess.setZero();
  if (f2 != 0) {
    const double w1 = f2 * inverse_lambda;
    for (int a = 0; a < slot_count_; ++a) {
      const int sa = slots_[static_cast<std::size_t>(a)];
      const double ga = w1 * g_sum[sa];
      hess(sa, sa) += ga * g_sum[sa];
      for (int b = a + 1; b < slot_count_; ++b) {
        const int sb = slots_[static_cast<std::size_t>(b)];
        const double hab = ga * g_sum[sb];
        hess(sa, sb) += hab;
        hess(sb, sa) += hab;
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    const Contribution& k = contributions_[static_cast<std::size_t>(i)];
    const Scratch& wi = w[i];
    if (wi.g == 0) continue;
    if (wi.d != 0) {
      const double wd = f1 * inverse_lambda * wi.d;
      if (k.slot >= 0) {
        hess(k.slot, k.slot) += wd;
      } else {
        for (int a = 0; a < k.slot_count; ++a) {
          const int sa = k.slots[static_cast<std::size_t>(a)];
          const double ga = wd * wi.grad[sa];
          hess(sa, sa) += ga * wi.grad[sa];
          for (int b = a + 1; b < k.slot_count; ++b) {
            const int sb = k.slots[static_cast<std::size_t>(b)];
            const double hab = ga * wi.grad[sb];
            hess(sa, sb) += hab;
            hess(sb, sa) += hab;
          }
        }
      }
    }
    if (k.derived >= 0) {
      const DerivedComponent& dc = derived_[static_cast<std::size_t>(k.derived)];
      if (dc.has_hessian()) dc.evaluate_into(c, nullptr, &hess, f1 * wi.g);
    }
  }
  return value;
}

double ConnectorPotential::evaluate_max(const Vector6& c, PotentialValue* out, Want want) const {
  const int n = contribution_count();
  std::array<double, kInlineContributions> inline_x;
  std::vector<double> heap_x;
  double* x = inline_x.data();
  if (n > kInlineContributions) {
    heap_x.resize(static_cast<std::size_t>(n));
    x = heap_x.data();
  }
  double m = 0;
  for (int i = 0; i < n; ++i) {
    const Contribution& k = contributions_[static_cast<std::size_t>(i)];
    const double e = k.slot >= 0 ? c[k.slot]
                                 : derived_[static_cast<std::size_t>(k.derived)].value(c);
    x[i] = (e - k.shift) / k.scale;
    m = std::max(m, std::fabs(x[i]));
  }
  const double zero = kZeroTolerance * m;

  // Strictly greater: among tied contributions the lowest data-line index wins (§2.5).
  int best = -1;
  double best_value = -std::numeric_limits<double>::infinity();
  double best_h = 0;
  for (int i = 0; i < n; ++i) {
    const Contribution& k = contributions_[static_cast<std::size_t>(i)];
    double p = 0;
    const double h = apply_function(k.function, x[i], zero, p);
    if (k.sign * p > best_value) {
      best_value = k.sign * p;
      best = i;
      best_h = h;
    }
  }
  if (!out) return best_value;
  out->active = best;
  const Contribution& k = contributions_[static_cast<std::size_t>(best)];
  // ∂P/∂E_k = s_k H_k'/R_k; the Hessian in E is 0, and in c only the curvature of a derived E_k
  // remains (chain rule of §2.4).
  const double nk = k.sign * best_h * k.inverse_scale;
  Matrix6* hess = want == Want::Hessian ? &out->hessian : nullptr;
  if (hess) hess->setZero();
  if (k.slot >= 0) {
    out->gradient.setZero();
    out->gradient[k.slot] = nk;
  } else {
    derived_[static_cast<std::size_t>(k.derived)].evaluate_into(c, &out->gradient, hess, nk);
    out->gradient *= nk;
  }
  return best_value;
}

void ConnectorPotential::evaluate_contribution(int i, const Vector6& c, PotentialValue& out,
                                               bool hessian) const {
  const Contribution& k = contributions_.at(static_cast<std::size_t>(i));
  out.active = i;
  out.negative_base = false;
  if (hessian) out.hessian.setZero();
  double e = 0;
  if (k.slot >= 0) {
    out.gradient.setZero();
    out.gradient[k.slot] = 1.0;
    e = c[k.slot];
  } else {
    e = derived_[static_cast<std::size_t>(k.derived)].evaluate_into(
        c, &out.gradient, hessian ? &out.hessian : nullptr, 1.0);
  }
  // On its own the contribution has m = |X_i|, so only an exact zero is "zero" here.
  const double x = (e - k.shift) / k.scale;
  double p = 0;
  const double h = apply_function(k.function, x, kZeroTolerance * std::fabs(x), p);
  const double nk = k.sign * h * k.inverse_scale;
  out.value = k.sign * p;
  out.gradient *= nk;
  if (hessian) out.hessian *= nk;
}

}  // namespace clinch
