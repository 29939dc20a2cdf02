// What a procedure's driver sees of the problem beside NonlinearProblem (ARCHITECTURE.md "Key
// interfaces"): the set-up of a step, the time and conditions of an increment, the state between
// solves (keep, drop, active sets, events), and what the state says about a failure. Newton never
// sees it; the driver never sees an element.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/procedure_needs.hpp"
#include "src/model/history_model.hpp"
#include "src/solver/frequency_eigensolver.hpp"
#include "src/solver/newton.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

// What a *FREQUENCY step needs of the problem beside its tangent (frequency_step.hpp): the lumped
// mass of the free solved equations, and the name of each solved equation's nodal DOF ("U1@5",
// "UR3@Part-1.7"), empty for a multiplier.
struct FrequencyModel {
  LumpedMass mass;
  std::vector<std::string> dof_names;
};

class StepProblem {
 public:
  virtual ~StepProblem() = default;

  // ---- a step ----
  // Starts step `step` (0-based) of the deck: NLGEOM, and its conditions resolved against those
  // carried over from the converged state (keywords.md §13).
  virtual void begin_step(std::size_t step, bool nlgeom) = 0;
  // Records the conditions' values at the end of the step for the next one.
  virtual void end_step(double period, double total_time) = 0;
  virtual bool laws_symmetric() const = 0;   // every law's tangent is symmetric
  virtual bool has_multipliers() const = 0;  // multipliers make a symmetric matrix indefinite
  // Stores the tangent as an upper triangle (symmetric) or in full from the next evaluation on;
  // NonlinearProblem::pattern() is then that storage's.
  virtual void use_storage(bool symmetric) = 0;
  // What the laws of the model ask of every step's procedure (a line search, notes for the log).
  virtual ProcedureNeeds procedure_needs() const = 0;

  // ---- an increment ----
  // Sets the time and the conditions of the increment that ends at (step_time, total_time) and
  // starts it, adding `extrapolate_scale` times the last converged increment (0: none).
  virtual void begin_increment(double step_time, double total_time, double dt,
                               double extrapolate_scale) = 0;
  // The same for an increment of a dynamic step, integrated by `procedure`'s operator
  // (docs/dynamics.md), from the converged state without extrapolation. Before the step's first
  // increment the state and the conditions at the step start give the HHT α term and, with
  // INITIAL=YES, the initial accelerations.
  virtual void begin_dynamic_increment(double step_time, double total_time, double dt,
                                       const DynamicProcedure& procedure) = 0;
  // After a converged increment of a dynamic step that ends at (step_time, total_time) and is dt
  // long: its half-increment residual (docs/dynamics.md "Automatic incrementation"), the largest
  // |R| of a free nodal equation halfway through it, and that DOF ("U1@5"); `error` when the
  // state there cannot be evaluated. The state is left exactly as it was.
  struct HalfIncrementResidual {
    double value = 0.0;
    std::string dof;
    std::string error;
  };
  virtual HalfIncrementResidual half_increment_residual(double /*step_time*/,
                                                        double /*total_time*/, double /*dt*/) {
    return {};
  }
  // `--check-tangent`: the assembled tangent against finite differences at the start of the
  // increment, as a report for the log; the state is left exactly as it was.
  virtual std::string check_tangent(int step, int increment) = 0;

  // ---- a Riks step (docs/riks.md) ----
  // Sets the step's conditions at the load proportionality factor `lpf` (its ramps at τ = lpf),
  // leaving the state as it is; end_step then records the conditions where the step ended.
  virtual void set_load_factor(double lpf) = 0;
  // Following the path inside an increment (increment_path.hpp): each condition at its values
  // at step times `from` and `to` blended by `fraction` (0 at `from`, 1 at `to`, linear beyond
  // either), leaving the state as it is.
  virtual void set_increment_fraction(double from, double to, double fraction) = 0;
  // Whether a load of the step has another value at step time `to` than at `from` (the path
  // inside an increment is followed only under prescribed motion: past a limit point under a
  // load, the far equilibrium is reached by a jump, which a static step does not take).
  virtual bool loads_change(double from, double to) const = 0;
  // The current value of DOF `dof` (1–6) of global node `node`; 0 when the node has no such DOF.
  virtual double nodal_value(std::int32_t node, int dof) const = 0;

  // ---- a linear perturbation step (docs/perturbation.md) ----
  // Back to the conditions of the base state once a perturbation step (static or frequency) is
  // done; its state is left by revert(). A step's time τ scales its perturbation: its
  // conditions at step time τ are the base values plus τ times their magnitudes.
  virtual void end_perturbation_step() {}

  // ---- a frequency step (frequency_step.hpp) ----
  // The mass and DOF names under the conditions of the current increment.
  virtual FrequencyModel frequency_model() const { return {}; }

  // ---- between solves ----
  virtual void commit() = 0;  // the trial state becomes the converged one
  virtual void revert() = 0;  // back to the converged state (a cutback)
  // Updates the active set (stops) from the solved state; true when it changed, and the
  // increment then iterates on.
  virtual bool update_active_set() = 0;
  // Events of a converged, committed increment (locks engage, elements are deleted).
  virtual void end_increment() = 0;
  // Applies the events of a converged state that change the problem itself and require the
  // increment to be solved again (*CONNECTOR FAILURE releasing components): one log line each;
  // empty when there is none. The caller then reverts and re-solves the same increment.
  virtual std::vector<std::string> release_failed_components() = 0;
  // What the log reports at the end of a step (one line each): totals of the converged state.
  virtual std::vector<std::string> step_summary() const = 0;
  // What end_increment did that the log reports (one line each), taken once.
  virtual std::vector<std::string> take_events() = 0;
  // Warnings of the converged state for the log (one line each), taken once.
  virtual std::vector<std::string> take_warnings() { return {}; }
  // An attempt did not converge and the increment is tried again (STABILIZE's adaptive factor).
  virtual void attempt_failed() {}
  // What the laws asked for in the last evaluation: a time-step ratio (below 1: retry smaller;
  // above 1: grow at most so much), whether a result was unreliable, and why.
  virtual StepRequest step_request() const = 0;

  // ---- a failure ----
  // Why a Newton attempt failed, in the deck's terms (the DOF or multiplier of a zero pivot or of
  // a value that is not finite).
  virtual std::string describe_failure(const NewtonReport& report) const = 0;
  // A likely cause read from the failed (trial) state: a connector deleted next to
  // `failed_equation` (−1 if none), else a connector softening past its peak; empty when none.
  virtual std::string failure_note(int failed_equation) const = 0;
};

}  // namespace clinch
