// The state of a run (ARCHITECTURE.md principle 3): the solution (nodal values and connector
// multipliers), the nodal rotations of NLGEOM, the laws' history, the stop and lock active sets,
// each in a trial and a converged copy, and what the last evaluation computed for every
// connector. commit() keeps the trial state once an increment has converged, revert() drops it
// on a cutback. Nothing here evaluates anything: the connector elements write the results, and
// the output, the stop and lock updates and the next increment read them.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "src/assembly/analysis_plan.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

// Stop/lock status of a component (output CSLST, output-variables.md §2).
enum class StopStatus : std::uint8_t { Free = 0, Lower = 1, Upper = 2, Locked = 3 };

// What an evaluation computed for one connector (output-variables.md §2).
struct ConnectorResult {
  Vector6 position = Vector6::Zero();      // CP
  Vector6 change = Vector6::Zero();        // CU (constraint residual for constrained ones)
  Vector6 constitutive = Vector6::Zero();  // CCU
  Vector6 elastic = Vector6::Zero();       // CEF (includes RIGID multipliers)
  Vector6 multiplier = Vector6::Zero();    // CRF
  Vector6 friction = Vector6::Zero();      // CSF
  Vector6 viscous = Vector6::Zero();       // CVF
  Vector6 applied = Vector6::Zero();       // CCF
  Vector6 total = Vector6::Zero();         // CTF = CEF + CVF + CSF + CRF − CCF
  Vector6 velocity = Vector6::Zero();      // CV: B v in a dynamic step
  Vector6 acceleration = Vector6::Zero();  // CA: B a in a dynamic step
};

// A connector's active set (behaviors.md §5): trial and converged status per component, and the
// positions at which locks engaged.
struct ConnectorActiveSet {
  std::array<std::uint8_t, 6> status{}, status_n{};
  Vector6 lock_position = Vector6::Zero();
  // *CONNECTOR FAILURE (behaviors.md §5.3): the released components, for good once a converged
  // increment met a criterion (not reverted by a cutback), the constitutive motion their laws
  // stay frozen at, and which rules have fired.
  ComponentMask released = 0;
  Vector6 release_motion = Vector6::Zero();
  std::uint32_t fired = 0;
};

// Adds a law's request to `request`: the smallest ratio wins, with its message.
void merge_step_request(StepRequest& request, double ratio, bool unreliable,
                        const std::string& message);

struct AnalysisState {
  explicit AnalysisState(const AnalysisPlan& plan);

  void commit();
  void revert();

  Eigen::VectorXd x, x_n, dx_n;  // solution, last converged, last converged increment
  // NLGEOM node rotations, per node; empty (the identity) until the run first goes NLGEOM
  // (ConnectorSystem::set_nlgeom): a small-displacement run saves 144 bytes per node and their
  // copy at each commit.
  std::vector<Matrix3> rotation, rotation_n;
  // Dynamic steps (dynamic_terms.hpp): velocity and acceleration of every nodal equation, trial
  // and converged, and r_n = I − P at the converged state (the HHT α term); empty when no step
  // of the deck is dynamic. In a rank's plan over its own equations they run over every equation
  // (its ghost nodes follow its multipliers), and a multiplier's entries are not used (r_n's are
  // zero).
  Eigen::VectorXd v, v_n, a, a_n, r_n;
  std::vector<double> history, history_n;
  std::vector<Vector6> position_n;  // converged connector positions (angle branches, §3.6)
  std::vector<ConnectorActiveSet> active_sets;
  std::vector<ConnectorResult> results;
  StepRequest request;  // what the laws asked for in the last evaluation
};

}  // namespace clinch
