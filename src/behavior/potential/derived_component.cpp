// Evaluation of a derived component g(c) = Σ T(c) (derived-components-and-potentials.md §1.3,
// §1.4): one pass over the flattened terms for the value and gradient, the NORM-term curvature
// added on the listed components only.
#include "src/behavior/potential/derived_component.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "src/model/potential_queries.hpp"

namespace clinch {
namespace {

// §1.4: "zero" means r ≤ 1e-12·m, m the largest |y_j| of the whole derived component.
constexpr double kZeroTolerance = 1e-12;

}  // namespace

DerivedComponent DerivedComponent::compile(const ConnectorBehavior& behavior,
                                           std::string_view key) {
  DerivedComponent out;
  std::vector<const DerivedComponentTerm*> listed;
  for (std::int32_t index : derived_component_terms(behavior, key)) {
    const DerivedComponentTerm& t = behavior.derived_terms[static_cast<std::size_t>(index)];
    listed.push_back(&t);
    if (t.components.size() > 6 || t.components.size() != t.coefficients.size()) {
      throw std::invalid_argument("derived component '" + std::string(key) +
                                  "' has a malformed term");
    }
    Term term;
    term.op = t.op;
    term.sign = t.sign < 0 ? -1.0 : 1.0;
    term.count = static_cast<int>(t.components.size());
    for (int j = 0; j < term.count; ++j) {
      const int k = t.components[static_cast<std::size_t>(j)];
      if (k < 1 || k > 6) {
        throw std::invalid_argument("derived component '" + std::string(key) +
                                    "' lists component " + std::to_string(k));
      }
      term.slot[static_cast<std::size_t>(j)] = k - 1;
      term.coefficient[static_cast<std::size_t>(j)] = t.coefficients[static_cast<std::size_t>(j)];
      out.components_ = static_cast<ComponentMask>(out.components_ | (1u << (k - 1)));
    }
    if (term.op == DerivedOperator::Norm) out.has_norm_term_ = true;
    out.terms_.push_back(term);
  }
  if (listed.empty()) {
    throw std::invalid_argument("unknown derived component '" + std::string(key) + "'");
  }
  out.type_ = classify_terms(listed);
  return out;
}

double DerivedComponent::evaluate(const Vector6& c, Vector6* gradient, Matrix6* hessian) const {
  if (hessian) hessian->setZero();
  return evaluate_into(c, gradient, hessian, 1.0);
}

double DerivedComponent::evaluate_into(const Vector6& c, Vector6* gradient, Matrix6* hessian,
                                       double weight) const {
  if (gradient) gradient->setZero();
  double m = 0;
  for (const Term& t : terms_) {
    for (int j = 0; j < t.count; ++j) {
      m = std::max(m, std::fabs(t.coefficient[static_cast<std::size_t>(j)] *
                                 c[t.slot[static_cast<std::size_t>(j)]]));
    }
  }
  // §1.4: m = 0 means every y_j is zero, so every term is zero and the NORM and MACAULEY SUM
  // terms have zero derivatives. A SUM term keeps its constant gradient: "everything is zero"
  // is there to avoid forming 1/r from round-off, and a SUM term has no kink (§1.4 table:
  // "smooth"), so a sum-type (linear) potential has the same gradient at c = 0 as elsewhere.
  // This reading is a clinch choice.
  const double zero = kZeroTolerance * m;
  const double inv_m = m > 0 && has_norm_term_ ? 1.0 / m : 0.0;

  double value = 0;
  for (const Term& t : terms_) {
    if (m == 0 && t.op != DerivedOperator::Sum) continue;
    const auto& k = t.slot;
    const auto& C = t.coefficient;
    switch (t.op) {
      case DerivedOperator::Sum: {
        for (int j = 0; j < t.count; ++j) {
          const auto jj = static_cast<std::size_t>(j);
          value += t.sign * C[jj] * c[k[jj]];
          if (gradient) (*gradient)[k[jj]] += t.sign * C[jj];
        }
        break;
      }
      case DerivedOperator::MacauleySum: {
        // The bracket acts on each product (§1.3); H(0) = 0 (§1.4 table).
        for (int j = 0; j < t.count; ++j) {
          const auto jj = static_cast<std::size_t>(j);
          const double y = C[jj] * c[k[jj]];
          if (y > 0) {
            value += t.sign * y;
            if (gradient) (*gradient)[k[jj]] += t.sign * C[jj];
          }
        }
        break;
      }
      case DerivedOperator::Norm: {
        if (t.count == 1) {
          // |C·c_k|: no curvature away from 0, and the subgradient 0 at the kink (§1.4 table).
          // Treated apart so that the Hessian is exactly 0 rather than C² − (C·y/|y|)² round-off.
          const double y = C[0] * c[k[0]];
          const double r = std::fabs(y);
          if (r <= zero) break;
          value += t.sign * r;
          if (gradient) (*gradient)[k[0]] += y > 0 ? t.sign * C[0] : -t.sign * C[0];
          break;
        }
        // Scaled by 1/m so that the squares neither overflow nor underflow: r = m·ρ.
        std::array<double, 6> z{};
        double rr = 0;
        for (int j = 0; j < t.count; ++j) {
          const auto jj = static_cast<std::size_t>(j);
          z[jj] = C[jj] * c[k[jj]] * inv_m;
          rr += z[jj] * z[jj];
        }
        const double rho = std::sqrt(rr);
        const double r = m * rho;
        // r = 0 (relative): value, gradient and Hessian 0, the minimum-norm subgradient (§1.4).
        if (rho <= kZeroTolerance) break;
        value += t.sign * r;
        if (!gradient && !hessian) break;
        const double inv_rho = 1.0 / rho;
        std::array<double, 6> v{};  // ∂r/∂c_{k_j} = C_j·y_j/r
        for (int j = 0; j < t.count; ++j) {
          const auto jj = static_cast<std::size_t>(j);
          v[jj] = C[jj] * z[jj] * inv_rho;
          if (gradient) (*gradient)[k[jj]] += t.sign * v[jj];
        }
        if (hessian) {
          // ∂²T/∂c_{k_i}∂c_{k_j} = (s/r)(C_i C_j δ_ij − v_i v_j) (§1.4).
          const double w = weight * t.sign * inv_rho * inv_m;  // weight·s/r
          for (int i = 0; i < t.count; ++i) {
            const auto ii = static_cast<std::size_t>(i);
            (*hessian)(k[ii], k[ii]) += w * (C[ii] * C[ii] - v[ii] * v[ii]);
            for (int j = i + 1; j < t.count; ++j) {
              const auto jj = static_cast<std::size_t>(j);
              const double h = -w * v[ii] * v[jj];
              (*hessian)(k[ii], k[jj]) += h;
              (*hessian)(k[jj], k[ii]) += h;
            }
          }
        }
        break;
      }
    }
  }
  return value;
}

}  // namespace clinch
