// The nonlinear problem of a run (ARCHITECTURE.md "NonlinearProblem"): the analysis state, the
// conditions of the current increment, and the assembly of every connector and spring element
// into the residual and the tangent, stored as an upper triangle or in full as the step needs.
// Prescribed values move by Newton corrections: while they are short of their targets, the
// prescribed columns of the tangent go to the right-hand side (the predictor).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "base/scaled_norm.hpp"
#include "src/assembly/analysis_state.hpp"
#include "src/assembly/assembly_pattern.hpp"
#include "src/assembly/connector_element.hpp"
#include "src/assembly/constrained_elements.hpp"
#include "src/assembly/constrained_inertia.hpp"
#include "src/assembly/dependent_motion.hpp"
#include "src/assembly/dynamic_terms.hpp"
#include "src/assembly/energy_balance.hpp"
#include "src/assembly/increment_conditions.hpp"
#include "src/assembly/spring_element.hpp"
#include "src/assembly/stabilization_damping.hpp"
#include "src/parallel/communicator.hpp"
#include "src/parallel/halo_exchange.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

// Output quantities of one connector at the last evaluation (output-variables.md §2).
struct ConnectorOutput : ConnectorResult {
  std::array<std::uint8_t, 6> status{};  // CSLST
  // The laws' history (CUP, CUPEQ, CALPHAF, …): 0 where no law holds that output.
  double history_value(std::string_view output, int component) const;
  // The scalar CUPEQ (output-variables.md §2): the coupled plasticity's value if the element has
  // one; otherwise the largest over the components with uncoupled plasticity.
  double scalar_equivalent_plastic() const;

  struct LawHistory {
    std::span<const HistoryVariable> layout;
    std::span<const double> values;
  };
  std::array<LawHistory, LawStack::kMaxLaws> laws{};
};

class ConnectorSystem final : public NonlinearProblem {
 public:
  ConnectorSystem(const Model& model, const AnalysisPlan& plan);

  // ---- the current step and increment ----
  void set_nlgeom(bool nlgeom);
  // Stores the tangent as an upper triangle (symmetric) or in full from the next evaluation on.
  // An unsymmetric element tangent in symmetric storage is symmetrised (keywords.md §14).
  void use_storage(bool symmetric);
  bool symmetric_storage() const { return storage().symmetric; }
  void set_time(double time, double dt) {
    context_.time = time;
    context_.dt = dt;
  }
  bool nlgeom() const { return context_.nlgeom; }
  IncrementConditions& conditions() { return conditions_; }
  // The prescribed targets moved within the increment (a path followed inside it ramps them with
  // its parameter: increment_path.hpp): the predictor takes the state to them again.
  void prescribed_targets_moved() { update_prescribed_predictor(); }
  // Starts an increment: with `extrapolate_scale` ≠ 0, adds that times the last converged
  // increment to the DOFs (finite rotations excepted). Prescribed DOFs do not jump to their
  // targets (finite rotations excepted): the next correction takes them there, the free DOFs
  // following linearly.
  void start_increment(double extrapolate_scale);
  bool is_prescribed(int equation) const { return conditions_.is_prescribed(equation); }
  // ---- dynamic steps (dynamic_terms.hpp) ----
  // The integration operator of the next increments, of length dt; null: a static increment,
  // which has no velocity.
  void set_integration(const DynamicProcedure* procedure, double dt);
  // At the start of a dynamic step, before its first increment's conditions: r₀ = I₀ − P₀ of
  // the converged state (the HHT α term) and, with `initial_acceleration`, a₀ = M⁻¹(−r₀).
  void start_dynamic_step(bool initial_acceleration);
  // The half-increment residual of the solved increment (docs/dynamics.md "Automatic
  // incrementation"): the equations of motion at the state halfway through it
  // (NewmarkIncrement::set_half_increment_state) under the conditions the caller has applied for
  // that time, in the HHT form of the Abaqus Theory Manual ("Implicit dynamic analysis"),
  // M a + (1 + α)(I − P) − (α/2)(r₀ + r₋₁) with r = I − P at the start of this increment and
  // of the one before (r₀ in a step's first increment). `value` is the largest |R| of a
  // free nodal equation, `equation` that equation (−1: none). It moves the state: the caller
  // takes a snapshot before and restores it after.
  struct HalfIncrementResidual {
    double value = 0.0;
    int equation = -1;
    EvalStatus status;
  };
  HalfIncrementResidual half_increment_residual();

  // ---- automatic stabilization (stabilization_damping.hpp) ----
  // Starts a step of `period` with `settings` (null: none); its log line joins the events.
  void begin_stabilization(const StaticStabilization* settings, double period);
  // An attempt that did not converge is being retried (the adaptive factor grows).
  void attempt_failed() { stabilization_.attempt_failed(events_); }
  std::vector<std::string> take_warnings() { return std::move(warnings_); }

  // ---- NonlinearProblem ----
  // The solved equations: every equation but the dependent ones (dependent_dofs.hpp); residuals
  // and corrections are in this numbering, the state and the conditions in the equations'.
  int size() const override { return plan_.dependents.solved_count(plan_.dofs); }
  int equation_of_solved(int solved) const { return plan_.dependents.equation(solved); }
  const SparseMatrix& pattern() const override { return storage().matrix; }
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override;
  void apply_correction(const Eigen::VectorXd& correction) override;
  bool moving_prescribed() const override { return predicting_; }
  void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
               IterationNorms& norms) const override;
  // Vectors by rows (docs/parallel.md): the owned rows of this rank, the reductions over the
  // ranks and the global number of a solved equation.
  int owned_size() const override { return halo_ ? plan_.solved_layout.owned : size(); }
  double sum_over_ranks(double mine) const override;
  double max_over_ranks(double mine) const override;
  int global_equation(int solved) const override { return plan_.solved_layout.global_of(solved); }
  // Translations count as they are, rotations times L̄, multipliers not at all (docs/riks.md).
  void path_weights(Eigen::VectorXd& weights) const override;
  // The LPF history column (docs/riks.md): a Riks step's load proportionality factor; in other
  // steps the fraction of the step's ramps, step time / period.
  void set_load_factor(double factor) { load_factor_ = factor; }
  double load_factor() const { return load_factor_; }

  // ---- between solves (StepProblem, connector_step_problem.hpp, passes these on) ----
  void commit();
  void revert() { state_.revert(); }
  bool update_active_set();
  void end_increment();
  std::vector<std::string> take_events() { return std::move(events_); }
  std::string failure_note(int failed_equation, bool riks = false) const;
  DamageChange damage_change() const override;
  std::vector<std::string> step_summary() const;
  std::vector<std::string> release_failed_components();
  StepRequest step_request() const { return state_.request; }

  // ---- distributed runs (docs/parallel.md) ----
  // From the next evaluation on, evaluates only this rank's share of the connectors and springs
  // and sums the forces over the ranks after each evaluation (connector_system_exchange.cpp).
  // A plan with a share of the elements holds the rank's own, whose results stay here; with a
  // whole plan the ranks also exchange the results, so that every rank holds what a serial
  // evaluation gives. Without it every element is evaluated here. `by_rows`: the tangent is
  // this rank's part (SparseMatrix::partial), which the distributed solver sums; otherwise the
  // ranks sum the whole tangent and each holds it. Called before the first evaluation.
  void distribute(Communicator& communicator, bool by_rows);
  bool assembled_by_rows() const { return by_rows_; }
  // The vectors run over this rank's own rows and ghosts (AnalysisPlan::layout): a nodal output
  // is the owner's, the others give 0 (history columns sum the ranks' parts).
  bool vectors_by_rows() const { return halo_.has_value(); }
  // The nodal equations of this rank's own rows (the first ones), or every nodal equation.
  int owned_node_equations() const;

  // ---- diagnostics ----
  // Everything an evaluation, a correction or a change of the conditions can change: the state,
  // the conditions, the prescribed predictor and the last evaluation's results. A diagnostic that
  // moves the state (the tangent check) takes one before and restores it after, so that the run
  // goes on exactly as it would have without it.
  struct Snapshot {
    AnalysisState state;
    IncrementConditions conditions;
    Eigen::VectorXd internal, predictor;
    bool predicting;
    std::vector<SpringResult> springs;
    std::vector<std::uint8_t> multiplier_active;
    ForceEntries element_forces, inertia_entries;
    Eigen::VectorXd constraint_load;
    std::string dependent_failure;
  };
  Snapshot snapshot() const;
  void restore(const Snapshot& snapshot);

  // ---- results of the last evaluation ----
  double value(int equation) const { return state_.x[equation]; }
  double converged_value(int equation) const { return state_.x_n[equation]; }
  // Nodal value of DOF `dof` of `node` (0 when inactive): U, UR (rotation vector under NLGEOM).
  double nodal_value(std::int32_t node, int dof) const;
  double reaction(std::int32_t node, int dof) const;  // RF/RM: internal − applied, prescribed DOFs
  double applied_load(std::int32_t node, int dof) const;  // CF/CM
  // V/VR (order 1) and A/AR (order 2) of DOF `dof` of `node` (0 without a dynamic step).
  double nodal_rate(std::int32_t node, int dof, int order) const;
  // The converged velocity (order 1) or acceleration (2) of `equation`, 0 without a dynamic step.
  double converged_rate(int equation, int order) const;
  // The value of `equation` at the end of the increment whose velocity (order 1) or acceleration
  // (2) there is `rate`, by the step's operator from the converged state (*BOUNDARY,
  // TYPE=VELOCITY or ACCELERATION; docs/dynamics.md); the converged value outside a dynamic
  // increment.
  double displacement_of_rate(int equation, int order, double rate) const;
  // The same for a quantity whose converged value, rate and acceleration are u0, v0 and a0: a
  // connector component's CU, CV and CA (*CONNECTOR MOTION, TYPE=VELOCITY or ACCELERATION;
  // docs/dynamics.md; component_values asks for them).
  double value_of_rate(double u0, double v0, double a0, int order, double rate) const;
  // The converged CU (order 0), CV (1) or CA (2) of that component (a connector whose record
  // this rank's plan holds).
  double converged_component(std::size_t connector, int component, int order) const;
  // Values of connector components on every rank, whichever rank holds the connector: called by
  // every rank alike under a distributed model (the holders' values are summed).
  struct ComponentQuery {
    enum Quantity { Value, Velocity, Acceleration, Reaction };  // converged CU, CV, CA; last CRF
    std::size_t connector = 0;                                  // global index
    int component = 1;
    Quantity quantity = Value;
  };
  std::vector<double> component_values(std::span<const ComponentQuery> queries) const;
  // The whole-model energies at the last converged increment (plan().energies; else zero).
  ModelEnergies energies() const;
  // Connector `connector` (global index), of those whose records this rank's plan holds.
  ConnectorOutput connector_output(std::size_t connector) const;
  bool holds_connector(std::size_t connector) const { return plan_.holds_connector(connector); }
  // Spring `spring` (global index), of those whose results this rank holds (holds_spring: every
  // one unless the plan holds a share of the elements).
  const SpringResult& spring_output(std::size_t spring) const {
    return springs_[spring - plan_.first_spring];
  }
  bool holds_spring(std::size_t spring) const {
    return spring >= plan_.first_spring && spring < plan_.first_spring + springs_.size();
  }
  // Under a plan with a share of the elements, what each rank found about its own connectors,
  // joined (every rank calls it alike): every rank's lines in rank order (element order), and
  // whether any rank says yes. Without one, what this process found.
  std::vector<std::string> lines_of_every_rank(std::vector<std::string> mine) const;
  // Under vectors by rows, the largest of the ranks' `value` (≥ 0, or −1 for none) and the `text`
  // of the rank that has it (the first such rank): one reduction of a number per rank and one
  // broadcast. Unchanged otherwise.
  void join_largest(double& value, std::string& text) const;
  bool any_rank(bool mine) const;
  // Element-wise sums over the ranks of a distributed run, in place (nothing on one process):
  // for outputs whose parts each rank holds (history columns of springs).
  void sum_over_ranks(std::span<double> values) const {
    if (communicator_) communicator_->sum(values);
  }
  const AnalysisPlan& plan() const { return plan_; }
  // The motion of the dependent DOFs with its gradients at the current state.
  DependentMotion dependent_motion() const;

 private:
  template <typename Residual, typename Tangent>
  void scatter(std::span<const int> equations, std::size_t offset, const Residual& r,
               const Tangent& k, bool symmetrize, SparseMatrix* tangent);
  // Scatters an element's local system, condensed first when it has dependent DOFs.
  void scatter_element(const LocalEquations& l, std::int32_t expansion, std::size_t offset,
                       const LocalSystem& local, bool symmetrize, SparseMatrix* tangent);
  // After the sums: the loads on dependent DOFs move to the DOFs they depend on, the curvature
  // of the maps (NLGEOM) joins the tangent, and the dependent rows become the identity.
  void finish_dependent_rows(Eigen::VectorXd& residual, SparseMatrix* tangent);
  void add_curvature(const CurvatureEntry& entry, SparseMatrix& tangent);
  // The dependent DOFs (and followers' rotations) from the independent ones.
  void update_dependents();
  bool connector_finite(std::size_t c, const LocalSystem& local) const;
  // The entries of q̃ (ForceEntries): an element's nodal contributions, and a connector's
  // component forces.
  int force_field(int equation) const;
  void add_force_entries(const LocalEquations& l, int nodal_count, const LocalSystem& local);
  void add_component_forces(const ConnectorResult& result);
  bool is_finite_rotation(int equation) const;
  void snap_to_target(int equation, double before);
  void update_prescribed_predictor();
  void snap_prescribed_rotations();
  void apply_prescribed_rotations();
  void finish_prescribed_correction(const Eigen::VectorXd& dx);
  // After a distributed evaluation: the first failure of any rank on every rank, else the sums,
  // results and requests of all ranks.
  void exchange(SparseMatrix* tangent, EvalStatus& status);
  void exchange_step_requests();
  // Vectors by rows: the norms of this rank's rows joined with the other ranks' (measure), the
  // loads' entries of q̃ among them.
  void join_norms(IterationNorms& norms, ForceEntries& loads, ScaledNorm& residual_norm,
                  ScaledNorm& correction_norm) const;
  // Whether a nodal equation is this rank's to report (the owner's, under vectors by rows).
  bool reports(int equation) const { return equation >= 0 && plan_.layout.owns(equation); }

  const Model& model_;
  const AnalysisPlan& plan_;
  ConnectorElements elements_;
  AnalysisState state_;
  IncrementConditions conditions_;
  ElementContext context_;
  // The storages built so far (symmetric, full) and the one in use: built when first asked for,
  // once the system knows whether it is distributed; the symmetric one until use_storage
  // chooses.
  mutable std::unique_ptr<AssemblyPattern> symmetric_pattern_, full_pattern_;
  mutable const AssemblyPattern* pattern_ = nullptr;
  const AssemblyPattern& storage() const;
  const AssemblyPattern& build_storage(bool symmetric) const;
  std::unique_ptr<LocalSystem> local_;
  std::vector<SpringResult> springs_;
  std::vector<std::uint8_t> multiplier_active_;
  Eigen::VectorXd internal_;
  ForceEntries element_forces_;   // of the last evaluation
  ForceEntries inertia_entries_;  // of the inertia of the nodes this rank adds (own_inertia)
  // K_fp·(target − u)_p while prescribed DOFs are short of their targets (predicting_).
  Eigen::VectorXd predictor_;
  bool predicting_ = false;
  std::vector<std::uint8_t> deleted_;           // per connector: deleted by damage (§7.4)
  Communicator* communicator_ = nullptr;        // null: a serial run
  std::optional<HaloExchange> halo_;            // vectors by rows: their ghost entries
  bool by_rows_ = false;                        // the tangent is this rank's part
  ItemRange owned_connectors_, owned_springs_;  // the elements this process evaluates
  std::vector<std::size_t> history_bytes_;      // per rank: the bytes of its connectors' history
  std::vector<std::string> events_;
  std::vector<std::string> warnings_;  // for the log, once (stabilization energy)
  DependentMotion motion_;
  CondensedLocal condensed_;
  std::vector<CurvatureEntry> curvature_;
  // The loads on dependent DOFs as they act on the DOFs they depend on (Tᵀ f): part of the
  // reaction of a prescribed reference node.
  Eigen::VectorXd constraint_load_;
  std::string dependent_failure_;  // why the dependent DOFs could not follow the last correction
  std::optional<NewmarkIncrement> newmark_;  // set during a dynamic step
  bool rates_frozen_ = false;  // evaluate at the converged velocities (start_dynamic_step)
  // M a per equation at the last evaluation, with what inertia on dependent DOFs puts on the
  // independent ones (reactions).
  Eigen::VectorXd inertia_force_;
  // The inertia blocks with dependent DOFs at the current gradients (constrained_inertia.hpp).
  std::vector<MappedInertiaBlock> constrained_inertia_;
  // I − P at the current state over the independent equations, loads on dependent DOFs moved
  // onto them (the right-hand side of INITIAL=YES).
  Eigen::VectorXd static_residual() const;
  // The HHT α term of the converged state (AnalysisState::r_n) from static_residual(), at the
  // start of a step or after an increment: with dependent DOFs, the force on each at its own row.
  Eigen::VectorXd hht_residual(Eigen::VectorXd condensed, bool start) const;
  // The inertia force (M a)/(1 + α) on dependent equation `eq` (the curvature of its map).
  double dependent_inertia(int eq) const;
  // r₋₁ = I − P at the start of the step's last converged increment (r₀ in its first): the
  // lagged term of the half-increment residual.
  Eigen::VectorXd r_before_;
  // CU, CV and CA of every connector at the converged state (kept at each commit and at a
  // dynamic step's start); empty before the first: the initial state's evaluation holds them.
  struct ComponentRates {
    Vector6 value, velocity, acceleration;
  };
  std::vector<ComponentRates> converged_components_;
  void keep_converged_components();
  std::optional<EnergyBalance> energy_;  // plan().energies
  Eigen::VectorXd external_force_;       // loads, and at prescribed DOFs what holds them
  double initial_kinetic_ = 0.0;         // ETOTAL at the start (*INITIAL CONDITIONS)
  StabilizationDamping stabilization_;
  Eigen::VectorXd stabilization_force_;  // F_v per equation at the last evaluation
  EnergyForces energy_forces();
  // ALLKE of the velocities `v` (of every rank's nodes under vectors by rows).
  double kinetic(const Eigen::VectorXd& v, const std::vector<Matrix3>& rotations) const;
  // What holds prescribed equation `eq` where it is: the elements' and the inertia's force on
  // it, less the loads moved onto it from dependent DOFs (its reaction plus its own load).
  double holding_force(int eq) const;
  // With dependent DOFs: the residual over every equation, and a correction expanded to them.
  Eigen::VectorXd full_residual_, full_correction_;
  double load_factor_ = 0.0;  // the LPF column's value
};

}  // namespace clinch
