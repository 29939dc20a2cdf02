// The nonlinear problem of a run (ARCHITECTURE.md "NonlinearProblem"): nodal displacements and
// rotations, connector multipliers, behaviour history, and the conditions of the current
// increment. evaluate() runs every connector and spring (kinematics, behaviour, constraints) and
// scatters into the residual and the fixed-pattern tangent; commit()/revert() keep or drop the
// trial state; the active set of stops and the locks change only between Newton solves.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "src/assembly/analysis_plan.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

// Stop/lock status of a component (output CSLST, output-variables.md §2).
enum class StopStatus : std::uint8_t { Free = 0, Lower = 1, Upper = 2, Locked = 3 };

// Output quantities of one connector at the current state (output-variables.md §2).
struct ConnectorOutput {
  Vector6 position = Vector6::Zero();      // CP
  Vector6 change = Vector6::Zero();        // CU (constraint residual for constrained ones)
  Vector6 constitutive = Vector6::Zero();  // CCU
  Vector6 elastic = Vector6::Zero();       // CEF (includes RIGID multipliers)
  Vector6 multiplier = Vector6::Zero();    // CRF
  Vector6 applied = Vector6::Zero();       // CCF
  Vector6 total = Vector6::Zero();         // CTF = CEF + CRF − CCF
  std::array<std::uint8_t, 6> status{};    // CSLST
  BehaviorState behavior;                  // CUP, CUPEQ, CALPHAF (plastic behaviours)
};

class ConnectorSystem final : public NonlinearProblem {
 public:
  ConnectorSystem(const Model& model, const AnalysisPlan& plan);
  ~ConnectorSystem() override;  // in the .cpp, where LocalSystem is complete

  // ---- the current increment's conditions ----
  void set_nlgeom(bool nlgeom);
  void set_time(double time, double dt) {
    time_ = time;
    dt_ = dt;
  }
  bool nlgeom() const { return nlgeom_; }
  void clear_conditions();
  void prescribe(int equation, double value);  // *BOUNDARY target of this increment
  void add_load(int equation, double value);   // *CLOAD (and released reactions)
  void prescribe_motion(int connector, int component, double value);
  void add_connector_load(int connector, int component, double value);
  // Starts an increment: with `extrapolate_scale` ≠ 0, adds that times the last converged
  // increment to the DOFs (finite rotations excepted). Prescribed DOFs do not jump to their
  // targets (finite rotations excepted): the next correction takes them there, the free DOFs
  // following linearly.
  void start_increment(double extrapolate_scale);
  bool is_prescribed(int equation) const { return prescribed_[static_cast<std::size_t>(equation)]; }

  // ---- NonlinearProblem ----
  int size() const override { return plan_.dofs.equations(); }
  const SparseMatrix& pattern() const override { return plan_.pattern; }
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override;
  void apply_correction(const Eigen::VectorXd& correction) override;
  bool moving_prescribed() const override { return predicting_; }
  void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
               IterationNorms& norms) const override;

  // ---- state changes between solves ----
  void commit();
  void revert();
  // Stops (behaviors.md §5.1): activates violated limits and releases limits whose force has
  // the wrong sign. Returns true when the set changed (the increment then iterates on).
  bool update_stops();
  // Locks (§5.2): engages the locks whose criterion the converged state meets. Call after commit.
  void engage_locks();

  // ---- results ----
  double value(int equation) const { return x_[equation]; }
  // Nodal value of DOF `dof` of `node` (0 when inactive): U, UR (rotation vector under NLGEOM).
  double nodal_value(std::int32_t node, int dof) const;
  double reaction(std::int32_t node,
                  int dof) const;  // RF/RM: internal − applied at prescribed DOFs
  double applied_load(std::int32_t node, int dof) const;  // CF/CM
  double converged_value(int equation) const { return x_n_[equation]; }
  ConnectorOutput connector_output(std::size_t connector);
  // S11/E11 of a spring.
  void spring_output(std::size_t spring, double& force, double& delta) const;
  const AnalysisPlan& plan() const { return plan_; }

 private:
  struct Dynamic {                         // per-connector state that only some connectors need
    Vector6 position_n = Vector6::Zero();  // last converged positions (angle branches, §3.6)
    Vector6 motion_n = Vector6::Zero();    // last converged constitutive motion
    std::array<std::uint8_t, 6> status{}, status_n{};
    Vector6 lock_position = Vector6::Zero();
    Vector6 motion_target = Vector6::Zero();
    ComponentMask motion = 0;
    Vector6 connector_load = Vector6::Zero();
  };
  struct LocalSystem;
  bool needs_dynamic(const ConnectorRecord& r) const;
  Dynamic* dynamic(std::size_t connector);
  const Dynamic* dynamic(std::size_t connector) const;
  Dynamic& ensure_dynamic(std::size_t connector);
  NodePose pose(std::int32_t node) const;
  // One connector: prepare (kinematics, the behaviour's input), integrate its behaviour,
  // finish (constraints, the local residual and tangent, `output`). evaluate() runs the three
  // stages itself to integrate connectors that share a behaviour in batches.
  EvalStatus evaluate_connector(std::size_t c, LocalSystem& local, bool want_tangent,
                                ConnectorOutput* output);
  EvalStatus prepare_connector(std::size_t c, LocalSystem& local, bool want_tangent,
                               BehaviorOutput& behavior);
  BehaviorInput behavior_input(std::size_t c, const LocalSystem& local) const;
  EvalStatus behavior_status(std::size_t c, const BehaviorOutput& behavior,
                             IntegrationStatus status) const;
  EvalStatus finish_connector(std::size_t c, LocalSystem& local, const BehaviorOutput& behavior,
                              bool want_tangent, ConnectorOutput* output);
  // The connector's multiplier states, then its local system into the residual and tangent.
  void finish_scatter(std::size_t c, const LocalSystem& local, SparseMatrix* tangent);
  std::string label(std::size_t c) const;  // the element's label, for messages
  void evaluate_spring(const SpringRecord& s, LocalSystem& local, bool want_tangent, double* force,
                       double* delta) const;
  void scatter(const LocalEquations& l, const LocalSystem& local, SparseMatrix* tangent);
  void apply_prescribed_rotations();
  void snap_prescribed_rotations();
  bool is_finite_rotation(int equation) const;
  void snap_to_target(int equation, double before);
  void update_prescribed_predictor();
  void finish_prescribed_correction(const Eigen::VectorXd& dx);

  const Model& model_;
  const AnalysisPlan& plan_;
  bool nlgeom_ = false;
  double time_ = 0, dt_ = 0;
  std::vector<std::uint8_t> multiplier_active_;
  Eigen::VectorXd x_, x_n_, dx_n_;              // state, last converged, last converged increment
  std::vector<Matrix3> rotation_, rotation_n_;  // NLGEOM node rotations (identity otherwise)
  std::vector<double> history_, history_n_;
  std::vector<std::uint8_t> prescribed_;
  std::vector<int> prescribed_list_;
  Eigen::VectorXd target_, internal_, external_;
  // K_fp·(target − u)_p while prescribed DOFs are short of their targets (predicting_).
  Eigen::VectorXd predictor_;
  bool predicting_ = false;
  std::vector<std::int32_t> dynamic_of_connector_;
  std::vector<Dynamic> dynamics_;
  std::unique_ptr<LocalSystem> local_storage_;
  LocalSystem& local_;
};

}  // namespace clinch
