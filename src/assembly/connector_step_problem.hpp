// The connector system as a procedure's driver sees it (StepProblem): the steps' conditions
// (step_conditions.hpp) pushed into the system at each increment, the system's state between
// solves, the tangent check and the description of failures in the deck's terms.
#pragma once

#include "src/assembly/connector_system.hpp"
#include "src/assembly/step_conditions.hpp"
#include "src/solver/step_problem.hpp"

namespace clinch {

class ConnectorStepProblem final : public StepProblem {
 public:
  ConnectorStepProblem(const Model& model, ConnectorSystem& system);

  void begin_step(std::size_t step, bool nlgeom) override;
  void end_step(double period, double total_time) override;
  void end_perturbation_step() override;
  // A finite-rotation rotary inertia has an unsymmetric tangent (rotary_inertia_finite.hpp).
  bool laws_symmetric() const override {
    return system_.plan().laws_symmetric() && !finite_rotary_inertia_;
  }
  bool has_multipliers() const override { return system_.plan().has_multipliers; }
  void use_storage(bool symmetric) override { system_.use_storage(symmetric); }
  ProcedureNeeds procedure_needs() const override { return system_.plan().procedure_needs; }

  void begin_increment(double step_time, double total_time, double dt,
                       double extrapolate_scale) override;
  void begin_dynamic_increment(double step_time, double total_time, double dt,
                               const DynamicProcedure& procedure) override;
  HalfIncrementResidual half_increment_residual(double step_time, double total_time,
                                                double dt) override;
  std::string check_tangent(int step, int increment) override;

  void set_load_factor(double lpf) override;
  void set_increment_fraction(double from, double to, double fraction) override;
  bool loads_change(double from, double to) const override;
  double nodal_value(std::int32_t node, int dof) const override;

  FrequencyModel frequency_model() const override;

  void commit() override { system_.commit(); }
  void revert() override { system_.revert(); }
  bool update_active_set() override { return system_.update_active_set(); }
  void end_increment() override { system_.end_increment(); }
  std::vector<std::string> release_failed_components() override {
    return system_.release_failed_components();
  }
  std::vector<std::string> step_summary() const override { return system_.step_summary(); }
  std::vector<std::string> take_events() override { return system_.take_events(); }
  std::vector<std::string> take_warnings() override { return system_.take_warnings(); }
  void attempt_failed() override { system_.attempt_failed(); }
  StepRequest step_request() const override { return system_.step_request(); }

  std::string describe_failure(const NewtonReport& report) const override;
  // Newton names a solved equation (connector_system.hpp), by its global number under vectors by
  // rows.
  std::string failure_note(int failed_equation) const override {
    return system_.failure_note(equation_named(failed_equation), riks_);
  }

 private:
  const Model& model_;
  ConnectorSystem& system_;
  StepConditions conditions_;
  bool dynamic_step_started_ = false;   // this step's start state has been taken
  bool finite_rotary_inertia_ = false;  // the step is dynamic, under NLGEOM, with such a node
  bool riks_ = false;                   // the step is *STATIC, RIKS
  double period_ = 1.0;                 // of the step's ramps
  double total_time_ = 0.0;             // at the end of the increment
  double step_time_ = 0.0;              // the same in the step
  // The step time `step_time` with the analysis time it falls at.
  StepConditions::Time time_of(double step_time) const;
  // The equation of this rank's plan Newton's solved equation `solved` stands for (−1 when none,
  // or when under vectors by rows this rank does not hold it).
  int equation_named(int solved) const;
  double load_factor_ = 1.0;  // τ where the step's conditions end (1 but in a Riks step)
};

}  // namespace clinch
