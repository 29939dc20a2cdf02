// The constitutive interface of a connector element: a pure map from the committed state and a
// trial increment of the constitutive motion to the effective force and its tangent, all in
// component space (behaviors.md §1.3). Kinematics map nodal DOFs to components before this is
// called; the plan owns the history arrays and commits a trial history once an increment converges.
#pragma once

#include <span>
#include <string>

#include "base/small_types.hpp"
#include "src/model/section_model.hpp"

namespace clinch {

// Which tangent the caller needs: none (residual only), the elastic one (for a robust first
// iteration) or the consistent one (quadratic convergence).
enum class TangentRequest { None, Elastic, Consistent };

// Success; Unreliable (a result the caller may accept but should cut back on if the increment
// struggles); Failure (no result: the global solver cuts back, behaviors.md §1.3).
enum class IntegrationStatus { Success, Unreliable, Failure };

struct BehaviorInput {
  const Vector6& motion_old;  // constitutive motion u = p − ref at the last converged increment
  const Vector6& increment;   // u − motion_old (trial)
  double time = 0, dt = 0;
  std::span<const double> history_old;
  TangentRequest tangent = TangentRequest::Consistent;
};

struct BehaviorOutput {
  Vector6 force = Vector6::Zero();  // f^eff (slots of components the behaviour does not act on: 0)
  Matrix6 tangent = Matrix6::Zero();  // ∂f/∂u
  std::span<double> history_new;
  double suggested_dt_ratio = 1.0;
  std::string message;  // filled only on failure
};

// What a behaviour's history means, for output (output-variables.md §2: CUP, CUE, CUPEQ,
// CALPHAF). Components without plasticity read 0.
struct BehaviorState {
  Vector6 plastic_motion = Vector6::Zero();        // u^pl (CUP); CUE = CCU − CUP
  Vector6 equivalent_plastic = Vector6::Zero();    // ū^pl of each uncoupled plasticity (CUPEQn)
  ComponentMask uncoupled_plastic = 0;             // components with an uncoupled plasticity
  double coupled_equivalent_plastic = 0;           // ū^pl of the coupled plasticity (CUPEQC)
  bool has_coupled_plasticity = false;
  Vector6 back_force = Vector6::Zero();            // α (CALPHAF)
};

// A force–motion law in component space. `integrate` is const and never touches history_old, so
// one instance serves every element that shares the behaviour (ARCHITECTURE.md principle 2).
class Behavior {
 public:
  virtual ~Behavior() = default;
  virtual ComponentMask components() const = 0;  // components it acts on
  virtual int history_size() const = 0;          // doubles per element
  virtual bool tangent_is_symmetric() const = 0;
  virtual IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const = 0;
  // Reads a (committed or trial) history of this behaviour; a path-independent law leaves
  // `state` as it is.
  virtual void describe_state(std::span<const double> history, BehaviorState& state) const {
    (void)history;
    (void)state;
  }
};

}  // namespace clinch
