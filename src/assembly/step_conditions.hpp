// How boundary conditions, connector motions, loads and connector loads evolve within and across
// steps (keywords.md §13): each condition is resolved to an equation or a connector component,
// remembers how it was defined and its value at the end of the last step, and gives its value at
// any time of the current step. OP=NEW removals turn loads into ramps to zero and removed
// prescribed motions into decaying loads equal to their last reaction.
#pragma once

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "src/assembly/connector_system.hpp"
#include "src/model/model.hpp"
#include "src/solver/amplitude_function.hpp"

namespace clinch {

class StepConditions {
 public:
  StepConditions(const Model& model, const AnalysisPlan& plan);

  // Resolves the step's conditions against those carried over, reading start values (current
  // displacements, components, reactions) from the system's converged state.
  void begin_step(std::size_t step, ConnectorSystem& system);
  // Pushes the values at (step time, total time) into the system. τ = step_time / period.
  void apply(ConnectorSystem& system, double step_time, double total_time) const;
  // A time of the step: (step time, total time).
  using Time = std::pair<double, double>;
  // Pushes each condition's values at `from` and `to` blended by `fraction`:
  // v(from) + fraction (v(to) − v(from)), linear in it (increment_path.hpp).
  void apply_blended(ConnectorSystem& system, Time from, Time to, double fraction) const;
  // Whether any load (nodal, connector, gravity) has another value at `to` than at `from`.
  bool loads_change(Time from, Time to) const;
  // Records the values at the end of the step for the next one: at τ = 1, or at the load
  // proportionality factor a Riks step ended at.
  // Holds every condition at its value at the end of the step (a prescribed rate stays a rate,
  // as Abaqus carries a velocity condition into the next step).
  void end_step(double period, double total_time, double tau = 1.0);
  // After a linear perturbation step (docs/perturbation.md): back to the conditions of its base
  // state, as if the step had not been there.
  void end_perturbation();

 private:
  enum class Mode : std::uint8_t { Ramp, Jump, Amplitude, AmplitudeAbsolute, Fixed, Hold };
  struct Condition {
    Mode mode = Mode::Hold;
    double start = 0;      // v₀
    double magnitude = 0;  // m (Hold: the held value)
    std::int32_t amplitude = -1;
    int rate_order = 0;  // TYPE=VELOCITY (1) or ACCELERATION (2), *BOUNDARY or *CONNECTOR MOTION
    double value(double tau, double step_time, double total_time,
                 const std::vector<std::optional<AmplitudeFunction>>& amplitudes) const;
  };
  // Key: equation (BC, load), connector·8 + component (motion, connector load) or point mass·8 +
  // direction (gravity: the acceleration, which the mass multiplies).
  using Table = std::map<std::int64_t, Condition>;

  Condition define(const ConditionBlock& block, const Step& step, double magnitude, double start,
                   bool prescribed_kind) const;
  static double load_start(const Table& table, std::int64_t key);
  double value_at(const Condition& c, Time time) const;  // τ = step time / period
  // Pushes every condition's value(c) into the system.
  template <class Value>
  void push(ConnectorSystem& system, const Value& value) const;
  void carry_over(Table& table, bool replaced, bool load_kind, const Step& step, Table& removed);
  void begin_perturbation(const Step& step, ConnectorSystem& system);

  const Model& model_;
  const AnalysisPlan& plan_;
  std::vector<std::optional<AmplitudeFunction>> amplitudes_;
  Table boundaries_, loads_, motions_, connector_loads_, gravity_;
  // The MASS elements gravity loads (nodal_inertia.hpp), and the point mass of each element.
  std::vector<PointMass> point_masses_;
  std::vector<std::int32_t> point_mass_of_element_;
  // Removed prescribed conditions become loads that decay to zero over the step.
  Table released_loads_, released_connector_loads_;
  double period_ = 1.0;
  // Every table as the base state of a perturbation step left it (restored by end_perturbation).
  struct Tables {
    Table boundaries, loads, motions, connector_loads, gravity, released_loads,
        released_connector_loads;
  };
  std::optional<Tables> base_;
};

}  // namespace clinch
