// A compiled connector potential P(c) (derived-components-and-potentials.md §2): contributions
// X_i = (E_i − a_i)/R_i with E_i an intrinsic component or a derived component, P_i = H_i(X_i),
// combined by SUM (P = (Σ s_i P_i^α_i)^(1/β)) or MAX (P = max_i s_i P_i). Value, gradient and
// Hessian with respect to the six intrinsic components (§2.4 chain rule), with the conventions of
// the non-smooth points (§2.5 table). Plasticity and friction evaluate it at every local
// iteration, so evaluation never allocates; only the components the potential involves (§2.8)
// are ever read.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "src/behavior/potential/derived_component.hpp"
#include "src/behavior/potential/fixed_power.hpp"
#include "base/small_types.hpp"
#include "src/model/behavior_model.hpp"

namespace clinch {

struct PotentialValue {
  double value = 0;
  Vector6 gradient = Vector6::Zero();  // ∂P/∂c
  Matrix6 hessian = Matrix6::Zero();   // ∂²P/∂c² (filled only when asked for)
  int active = -1;  // MAX: the maximising contribution (lowest index among ties, §2.5); SUM: −1
  // SUM: the base S = Σ s_i P_i^α_i was negative and 1/β is not an integer, so P is the odd
  // extension sgn(S)·|S|^(1/β) of §2.3. The owner warns once per element when it sees this.
  bool negative_base = false;
  // SUM: n_i = ∂P/∂E_i of the first kSlopedContributions contributions (§2.4), which weigh the
  // subdifferential of a kink group (KinkGroup).
  static constexpr int kSlopedContributions = 8;
  std::array<double, kSlopedContributions> slope{};
};

// A set of components on which a SUM potential has a kink when they are all zero while their
// contribution is not: a NORM term or one component of a MACAULEY SUM term of a derived
// component (derived-components-and-potentials.md §1.4). With the group at zero, the
// subdifferential of P over its components is n_i·(C∘ζ) with ‖ζ‖ ≤ 1 (NORM) or ζ ∈ [0, 1]
// (MACAULEY), C the term's coefficients (sign included) and n_i the slope of its contribution.
// Only groups whose components appear nowhere else in the potential are listed, so that the
// subdifferential is exactly that set; the plastic return uses them to hold a group at zero.
struct KinkGroup {
  ComponentMask components = 0;
  bool macauley = false;
  int contribution = 0;
  Vector6 coefficient = Vector6::Zero();
};

class ConnectorPotential {
 public:
  // The potential `potential` of `behavior` (derived-component names resolved in that block).
  // The model must have passed validation.
  static ConnectorPotential compile(const ConnectorBehavior& behavior, const Potential& potential);

  // P(c), ∂P/∂c and, with `hessian`, ∂²P/∂c².
  void evaluate(const Vector6& c, PotentialValue& out, bool hessian) const;
  double value(const Vector6& c) const;

  // One contribution on its own, as a surface of the multi-surface return of a MAX potential
  // (behaviors.md §6.6): value s_i·P_i, its gradient and (with `hessian`) its Hessian.
  void evaluate_contribution(int i, const Vector6& c, PotentialValue& out, bool hessian) const;

  int contribution_count() const { return static_cast<int>(contributions_.size()); }
  bool is_max() const { return op_ == PotentialOperator::Max; }
  double exponent() const { return beta_; }
  ComponentMask components() const { return components_; }  // §2.8
  ContributionType type() const { return type_; }
  const std::vector<KinkGroup>& kink_groups() const { return kink_groups_; }
  // The potential as a sum of groups, for the grouped return (grouped_return.hpp): true when it
  // is a SUM with every α_i = β ≥ 1, no shifts and positive signs, whose contributions are
  // intrinsic components under ABS or MACAULEY or derived components of NORM and MACAULEY SUM
  // terms with SIGN=POSITIVE, every component listed once. Then E_i = Σ of its groups' values
  // (an intrinsic ABS contribution is a one-component NORM group with C = 1), `groups` lists
  // them all and `scales` holds R_i per contribution.
  bool group_structure(std::vector<KinkGroup>& groups, std::vector<double>& scales) const;

 private:
  // What evaluate fills: the value only, or also the gradient, or also the Hessian.
  enum class Want : std::uint8_t { Value, Gradient, Hessian };

  struct Contribution {
    int slot = -1;        // intrinsic component − 1, or −1 for a derived component
    int derived = -1;     // index into derived_
    double scale = 1.0;   // R_i (X_i is formed by division, so that equal ratios tie exactly)
    double inverse_scale = 1.0;  // 1/R_i
    double alpha = 2.0, shift = 0.0, sign = 1.0;
    PotentialFunction function = PotentialFunction::Abs;
    FixedPower power;  // x^α_i
    int slot_count = 0;                // the components E_i depends on
    std::array<std::int8_t, 6> slots{};
  };

  double evaluate_sum(const Vector6& c, PotentialValue* out, Want want) const;
  void collect_kink_groups();
  // The kink groups of one derived-component term (§1.4): a NORM term is one group, a MACAULEY
  // SUM term one group per component, a SUM term none.
  static void append_term_groups(const DerivedComponent::Term& t, int contribution,
                                 std::vector<KinkGroup>& out);
  double evaluate_max(const Vector6& c, PotentialValue* out, Want want) const;

  std::vector<Contribution> contributions_;
  std::vector<DerivedComponent> derived_;
  PotentialOperator op_ = PotentialOperator::Sum;
  double beta_ = 2.0;
  double inverse_beta_ = 0.5;
  FixedPower beta_power_;  // S^(1/β)
  bool inverse_beta_is_integer_ = false;  // S^(1/β) is real for S < 0 (§2.3)
  bool homogeneous_ = true;               // every α_i = β: the scaled path of §2.4
  ComponentMask components_ = 0;
  int slot_count_ = 0;
  std::array<std::int8_t, 6> slots_{};  // the components of §2.8, in increasing order
  ContributionType type_ = ContributionType::Norm;
  std::vector<KinkGroup> kink_groups_;
};

}  // namespace clinch
