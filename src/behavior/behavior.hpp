// The constitutive interface of a connector element: a pure map from the committed state and a
// trial increment of the constitutive motion to a force and its tangent, all in component space
// (behaviors.md §1.3). Kinematics map nodal DOFs to components before this is called; the
// analysis state owns the history arrays and commits a trial history once an increment converges.
// A connector's laws form a stack in the order of §1.3 (elastic-plastic, damage, friction; damping
// in parallel): each law returns its own contribution, and may read what the laws before it
// produced (damage degrades it) and the connector's constraint forces (friction's contact force).
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "base/small_types.hpp"
#include "base/procedure_needs.hpp"
#include "src/model/section_model.hpp"

namespace clinch {

// Which tangent the caller needs: none (a residual only: output, line search, finite
// differences) or the consistent one (quadratic convergence).
enum class TangentRequest { None, Consistent };

// Success; Unreliable (a result the caller may use, but the law doubts it: the step driver does
// not let the next increment grow); Failure (no result: the step driver cuts back, §1.3).
enum class IntegrationStatus { Success, Unreliable, Failure };

// One slot of a law's history: the output variable it holds (output-variables.md §2, e.g. "CUP")
// and its component (1–6, 0 for a scalar). A slot that holds nothing for this instance of the law
// has an empty name.
struct HistoryVariable {
  std::string_view output;
  int component = 0;
};

struct BehaviorInput {
  const Vector6& motion_old;  // constitutive motion u = p − ref at the last converged increment
  const Vector6& increment;   // u − motion_old (trial)
  double time = 0, dt = 0;
  std::span<const double> history_old;
  TangentRequest tangent = TangentRequest::Consistent;
  // The force and tangent of the laws before this one in the stack (nullptr for the first).
  const Vector6* force_below = nullptr;
  const Matrix6* tangent_below = nullptr;
  const Matrix6* force_tangent_below = nullptr;  // their force against the constraint forces
  // The connector's constraint forces at the current iterate, per component: the multipliers of
  // its active constraints (constrained and RIGID components, stops, locks, connector motions),
  // 0 elsewhere. Set only for a law that needs_connector_forces().
  const Vector6* connector_forces = nullptr;
  // The trial history of the law right before this one and its layout (empty for the first):
  // damage reads the equivalent plastic motion of a coupled plasticity there (behaviors.md §7.1).
  std::span<const double> history_below = {};
  std::span<const HistoryVariable> layout_below = {};
};

struct BehaviorOutput {
  Vector6 force = Vector6::Zero();    // this law's force (0 on components it does not act on)
  Matrix6 tangent = Matrix6::Zero();  // ∂force/∂u
  // ∂force/∂(connector forces): column i against the constraint force of component i + 1. Read
  // only for a law that needs_connector_forces().
  Matrix6 force_tangent = Matrix6::Zero();
  std::span<double> history_new;
  // The step the law would like, as a ratio of the current time increment: below 1 the increment
  // is abandoned and retried that much smaller; otherwise the next increment grows at most so
  // much. Infinity (the default): no request.
  double suggested_dt_ratio = std::numeric_limits<double>::infinity();
  std::string message;  // why it failed, is unreliable, or asks for a smaller step
  std::string warning;  // a doubt about a valid result, for the run log (once per element and step)
};

// A quantity a law accumulates in its history that the run log reports after each step, summed
// over the connectors whose law holds it: "{what}: {sum} ({count} {holders})".
struct StepTotal {
  std::string_view what;     // "energy dissipated by the viscous regularisation of damage so far"
  std::string_view holders;  // "connectors with VISCOSITY"
  double value = 0;
};

// The connector force a law's force is reported as (output-variables.md §2): CEF, CVF or CSF.
enum class ForceKind { Elastic, Viscous, Friction };

// A force–motion law in component space. `integrate` is const and never touches history_old, so
// one instance serves every element that shares the behaviour (ARCHITECTURE.md principle 3).
class Behavior {
 public:
  virtual ~Behavior() = default;
  virtual ComponentMask components() const = 0;  // components it acts on
  // Its history, slot by slot (the size of the history is the size of the layout).
  virtual std::span<const HistoryVariable> history_layout() const = 0;
  virtual bool tangent_is_symmetric() const = 0;
  // True when its force depends on the connector's constraint forces; it then fills
  // force_tangent, and the element's tangent is unsymmetric.
  virtual bool needs_connector_forces() const { return false; }
  virtual ForceKind force_kind() const { return ForceKind::Elastic; }
  // True when the committed `history` says the element is deleted (damage, behaviors.md §7.4):
  // it then contributes no force, no stiffness and no constraint rows.
  virtual bool deletes_element(std::span<const double> /*history*/) const { return false; }
  // The damage `history` holds: the largest overall damage of the components (the scalar CDMG,
  // output-variables.md §2), which names a softening connector when Newton fails; 0 for a law
  // that does not damage.
  virtual double damage(std::span<const double> /*history*/) const { return 0.0; }
  // What `history` adds to the run log's summary of a step; none by default.
  virtual std::optional<StepTotal> step_total(std::span<const double> /*history*/) const {
    return std::nullopt;
  }
  // What the law asks of the procedure (a line search, notes for the log); nothing by default.
  virtual ProcedureNeeds procedure_needs() const { return {}; }
  virtual IntegrationStatus integrate(const BehaviorInput& in, BehaviorOutput& out) const = 0;

  std::size_t history_size() const { return history_layout().size(); }
};

// 1 on the components of `mask`, 0 elsewhere.
inline Vector6 mask_vector(ComponentMask mask) {
  Vector6 v;
  for (int i = 0; i < 6; ++i) v[i] = (mask >> i) & 1u ? 1.0 : 0.0;
  return v;
}

// Index of the slot that holds `output` of `component` in `layout`, −1 if none does.
int history_slot(std::span<const HistoryVariable> layout, std::string_view output, int component);

}  // namespace clinch
