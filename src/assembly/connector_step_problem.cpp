#include "src/assembly/connector_step_problem.hpp"

#include <algorithm>

#include "src/assembly/connector_tangent_check.hpp"
#include "src/assembly/failure_description.hpp"
#include "src/assembly/frequency_mass.hpp"
#include "src/assembly/rotary_inertia_finite.hpp"
#include "src/model/output_variables.hpp"

namespace clinch {

ConnectorStepProblem::ConnectorStepProblem(const Model& model, ConnectorSystem& system)
    : model_(model), system_(system), conditions_(model, system.plan()) {}

void ConnectorStepProblem::begin_step(std::size_t step, bool nlgeom) {
  system_.set_nlgeom(nlgeom);
  conditions_.begin_step(step, system_);
  dynamic_step_started_ = false;
  const Step& s = model_.history.steps[step];
  // A perturbation step's time is the scale of its perturbation (docs/perturbation.md).
  period_ = s.procedure && !s.is_perturbation() ? s.procedure->period : 1.0;
  load_factor_ = 1.0;
  riks_ = s.procedure && s.procedure->riks && !s.dynamic && !s.frequency;
  const bool stabilized = s.procedure && s.procedure->stabilize && !s.dynamic && !s.frequency;
  system_.begin_stabilization(stabilized ? &*s.procedure->stabilize : nullptr, period_);
  finite_rotary_inertia_ = s.dynamic && nlgeom && system_.plan().finite_rotary_inertia;
}

void ConnectorStepProblem::end_perturbation_step() { conditions_.end_perturbation(); }

void ConnectorStepProblem::end_step(double period, double total_time) {
  conditions_.end_step(period, total_time, load_factor_);
}

void ConnectorStepProblem::begin_increment(double step_time, double total_time, double dt,
                                           double extrapolate_scale) {
  system_.set_integration(nullptr, dt);
  system_.set_time(total_time, dt);
  total_time_ = total_time;
  step_time_ = step_time;
  system_.set_load_factor(step_time / period_);
  conditions_.apply(system_, step_time, total_time);
  system_.start_increment(extrapolate_scale);
}

void ConnectorStepProblem::begin_dynamic_increment(double step_time, double total_time, double dt,
                                                   const DynamicProcedure& procedure) {
  if (!dynamic_step_started_) {
    // The conditions at the step's start (time 0 of the step: a load of AMPLITUDE=STEP acts
    // there already, a ramped one still has its value of the previous step).
    conditions_.apply(system_, 0.0, total_time - step_time);
    system_.start_dynamic_step(procedure.initial_acceleration);
    dynamic_step_started_ = true;
  }
  system_.set_integration(&procedure, dt);
  system_.set_time(total_time, dt);
  total_time_ = total_time;
  system_.set_load_factor(step_time / period_);
  conditions_.apply(system_, step_time, total_time);
  system_.start_increment(0.0);
}

StepProblem::HalfIncrementResidual ConnectorStepProblem::half_increment_residual(double step_time,
                                                                                 double total_time,
                                                                                 double dt) {
  const ConnectorSystem::Snapshot before = system_.snapshot();
  const double half = 0.5 * dt;
  // The loads halfway; the half-increment state carries its own prescribed values.
  system_.set_time(total_time - half, half);
  conditions_.apply(system_, step_time - half, total_time - half);
  const ConnectorSystem::HalfIncrementResidual r = system_.half_increment_residual();
  system_.set_time(total_time, dt);
  system_.restore(before);
  HalfIncrementResidual out;
  out.value = r.value;
  if (!r.status.ok) {
    out.error = r.status.message;
    return out;
  }
  if (r.equation >= 0) {
    const DofMap& dofs = system_.plan().dofs;
    const Node& node = model_.nodes[static_cast<std::size_t>(dofs.node_of(r.equation))];
    out.dof = output_column_label("U", dofs.dof_of(r.equation)) + "@" +
              qualified_label(model_, node.instance, node.label);
  }
  // Under vectors by rows each rank measured its own rows.
  double value = r.equation >= 0 ? r.value : -1.0;
  system_.join_largest(value, out.dof);
  out.value = std::max(value, 0.0);
  return out;
}

void ConnectorStepProblem::set_load_factor(double lpf) {
  load_factor_ = lpf;
  system_.set_load_factor(lpf);
  conditions_.apply(system_, lpf * period_, total_time_);
}

StepConditions::Time ConnectorStepProblem::time_of(double step_time) const {
  return {step_time, total_time_ - step_time_ + step_time};
}

void ConnectorStepProblem::set_increment_fraction(double from, double to, double fraction) {
  system_.set_load_factor((from + fraction * (to - from)) / period_);
  conditions_.apply_blended(system_, time_of(from), time_of(to), fraction);
  system_.prescribed_targets_moved();
}

bool ConnectorStepProblem::loads_change(double from, double to) const {
  return conditions_.loads_change(time_of(from), time_of(to));
}

double ConnectorStepProblem::nodal_value(std::int32_t node, int dof) const {
  return system_.nodal_value(node, dof);
}

FrequencyModel ConnectorStepProblem::frequency_model() const {
  return clinch::frequency_model(model_, system_);
}

std::string ConnectorStepProblem::check_tangent(int step, int increment) {
  return clinch::check_tangent(system_, step, increment);
}

int ConnectorStepProblem::equation_named(int solved) const {
  if (solved < 0) return -1;
  if (system_.vectors_by_rows()) {
    const int local = system_.plan().solved_layout.local_of(solved);
    return local < 0 ? -1 : system_.equation_of_solved(local);
  }
  return system_.equation_of_solved(solved);
}

std::string ConnectorStepProblem::describe_failure(const NewtonReport& report) const {
  NewtonReport named = report;
  named.failed_equation = equation_named(report.failed_equation);
  if (!system_.vectors_by_rows()) {
    return clinch::describe_failure(model_, system_.plan(), named,
                                    [&](std::vector<std::string> mine) {
                                      return system_.lines_of_every_rank(std::move(mine));
                                    });
  }
  // Under vectors by rows the rank that owns the equation's row describes it from what it holds,
  // and every rank reports that description.
  const auto as_held = [](std::vector<std::string> mine) { return mine; };
  const EquationLayout& layout = system_.plan().layout;
  const bool owner = named.failed_equation >= 0 && layout.owns(named.failed_equation);
  if (!owner) named.failed_equation = -1;
  const std::string mine =
      owner ? clinch::describe_failure(model_, system_.plan(), named, as_held) : std::string();
  for (std::string& line : system_.lines_of_every_rank({mine})) {
    if (!line.empty()) return std::move(line);
  }
  named.failed_equation = -1;
  return clinch::describe_failure(model_, system_.plan(), named, as_held);
}

}  // namespace clinch
