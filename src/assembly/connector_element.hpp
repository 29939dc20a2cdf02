// One connector element as one pipeline (ARCHITECTURE.md principle 4, behaviors.md §1.3):
// kinematics (connection-types.md) → its constraint forces from the multipliers → the law stack
// (elastic-plastic, damage, friction; each law may read the constraint forces) → the constraint
// equations of constrained and RIGID components, stops, locks and connector motions. It produces
// the element's local residual and its full local tangent over its nodal columns and its
// multipliers, writes the laws' trial history and keeps what it computed in the state's results.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "src/assembly/analysis_state.hpp"
#include "src/assembly/increment_conditions.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

// An element's local system: residual and full tangent in its local equation order.
struct LocalSystem {
  KinematicsResult kinematics;
  Eigen::Matrix<double, kMaxLocalEquations, 1> r;
  Eigen::Matrix<double, kMaxLocalEquations, kMaxLocalEquations> k;
  std::array<std::uint8_t, 6> active{};  // multiplier rows in use
};

// What an element evaluation reads besides the state.
struct ElementContext {
  const IncrementConditions& conditions;
  bool nlgeom = false;
  double time = 0, dt = 0;
  // In a dynamic step: the velocities of the state are those of the step's operator, and
  // ∂v₁/∂u₁ (0 at a step's start state, whose velocities are the converged ones).
  bool dynamic = false;
  double dv_du = 0;
};

class ConnectorElements {
 public:
  ConnectorElements(const Model& model, const AnalysisPlan& plan) : model_(model), plan_(plan) {}

  // Connector record `c` (of the plan's records) at the state's trial values. The local tangent
  // only when `want_tangent`.
  EvalStatus evaluate(std::size_t c, const ElementContext& context, AnalysisState& state,
                      bool want_tangent, LocalSystem& local) const;
  std::string label(std::size_t c) const;  // the element's label, for messages

 private:
  EvalStatus evaluate_deleted(std::size_t c, const ElementContext& context, AnalysisState& state,
                              bool want_tangent, LocalSystem& local) const;

  const Model& model_;
  const AnalysisPlan& plan_;
};

// True when a law of connector `r` has deleted it at the committed state (damage, §7.4).
bool is_deleted(const ConnectorRecord& r, const AnalysisState& state);

// The pose of `node` in the state (zero displacement and identity rotation for the ground).
NodePose node_pose(const DofMap& dofs, const AnalysisState& state, std::int32_t node);

}  // namespace clinch
