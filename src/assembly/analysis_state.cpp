#include "src/assembly/analysis_state.hpp"

#include <algorithm>

namespace clinch {

void merge_step_request(StepRequest& request, double ratio, bool unreliable,
                        const std::string& message) {
  if (ratio < request.dt_ratio || (unreliable && request.message.empty())) {
    request.message = message;
  }
  request.dt_ratio = std::min(request.dt_ratio, ratio);
  request.unreliable = request.unreliable || unreliable;
}

AnalysisState::AnalysisState(const AnalysisPlan& plan)
    : x(Eigen::VectorXd::Zero(plan.dofs.equations())),
      x_n(x),
      dx_n(x),
      rotation(plan.small_displacement ? 0 : plan.dofs.nodes(), Matrix3::Identity()),
      rotation_n(rotation),
      // Over the nodal equations, the first ones; in a rank's plan over its own equations
      // (equation_layout.hpp), whose ghost nodes follow its multipliers, over every equation.
      v(Eigen::VectorXd::Zero(!plan.dynamic       ? 0
                              : plan.layout.local ? plan.dofs.equations()
                                                  : plan.dofs.node_equations())),
      v_n(v),
      a(v),
      a_n(v),
      r_n(v),
      history(plan.history_size, 0.0),
      history_n(history),
      active_sets(plan.connectors.size()),
      results(plan.connectors.size()) {
  position_n.reserve(plan.connectors.size());
  for (const ConnectorRecord& r : plan.connectors) {
    position_n.push_back(plan.kinematics[r.kinematics].initial_position());
  }
}

void AnalysisState::commit() {
  dx_n = x - x_n;
  x_n = x;
  rotation_n = rotation;
  v_n = v;
  a_n = a;
  history_n = history;
  for (std::size_t c = 0; c < results.size(); ++c) {
    position_n[c] = results[c].position;
    active_sets[c].status_n = active_sets[c].status;
  }
}

void AnalysisState::revert() {
  x = x_n;
  rotation = rotation_n;
  v = v_n;
  a = a_n;
  history = history_n;
  for (ConnectorActiveSet& a : active_sets) a.status = a.status_n;
}

}  // namespace clinch
