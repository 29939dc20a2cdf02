// A step's procedure (keywords.md §15): its time policy and what an increment means for it.
// *STATIC (static_step_procedure.hpp), *STATIC, RIKS (riks_procedure.hpp) and implicit *DYNAMIC
// (dynamic_step_procedure.hpp); each further step kind with increments is another
// implementation. The step driver runs any of them around the same increment attempt, Newton and
// StepProblem, and never asks which one it has. A *FREQUENCY step has no increments: the driver
// runs it through frequency_step.hpp.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "src/linalg/linear_solver.hpp"
#include "src/solver/step_problem.hpp"
#include "src/solver/time_stepper.hpp"

namespace clinch {

struct Step;

// Where an increment lies: it ends at `step_time` of the step and `total_time` of the analysis,
// is `dt` long, and the last converged increment of the step was `previous_dt` (0: none yet).
struct IncrementTimes {
  double step_time = 0.0;
  double total_time = 0.0;
  double dt = 0.0;
  double previous_dt = 0.0;
};

// How Newton treats this procedure's increments.
struct IncrementRules {
  bool accept_unconverged = false;  // an increment at the iteration limit is kept (DIRECT=NO STOP)
  bool fixed_increments = false;    // no increment can be cut, so Newton breaks its own cycles
};

// What a procedure's accuracy measure says of a converged increment (a dynamic step's
// half-increment residual, docs/dynamics.md "Automatic incrementation"): `ratio` below 1 rejects
// the increment and asks for an attempt that much smaller, as a law's request does; `accuracy` is
// the measure over its tolerance (NaN: none measured); `message` says both for the log.
struct IncrementAccuracy {
  double ratio = std::numeric_limits<double>::infinity();
  double accuracy = std::numeric_limits<double>::quiet_NaN();
  std::string message;
};

class Procedure {
 public:
  virtual ~Procedure() = default;
  virtual double period() const = 0;  // the step time at the step's end
  // A new time policy for one run of the step (its state starts at the step's start).
  virtual std::unique_ptr<TimeStepper> time_stepper() const = 0;
  virtual IncrementRules increment_rules() const = 0;
  // Starts the increment on `problem`: its times and conditions, and the predictor this
  // procedure uses from the converged state.
  virtual void begin_increment(StepProblem& problem, const IncrementTimes& times) const = 0;
  // What Newton solves in this step: the problem and the step's linear solver themselves, or
  // the system the procedure makes of them (RIKS: bordered by the arc length). Asked once the
  // step has begun and its solver is chosen; valid until the procedure ends.
  // After a converged attempt at the increment `times`: its accuracy, measured on `problem`
  // against a tolerance that may scale with `average_force` (q̄ of the converged iteration).
  virtual IncrementAccuracy check_increment(StepProblem& /*problem*/,
                                            const IncrementTimes& /*times*/,
                                            double /*average_force*/) const {
    return {};
  }
  virtual NonlinearProblem& newton_problem(NonlinearProblem& problem, StepProblem& /*step*/) {
    return problem;
  }
  virtual LinearSolver& newton_solver(LinearSolver& solver) { return solver; }
  // Why the step ended, when the procedure decides it (a Riks step's stopping criterion), for
  // the .sta and the log; empty when the step simply reached its period.
  virtual std::string end_reason() const { return {}; }
};

// The procedure of `step`: *DYNAMIC (dynamic_step_procedure.hpp) or *STATIC (also when the step
// names none: keywords.md §15); its increments end at the multiples of `output_intervals`
// (output_time_intervals, history_model.hpp).
std::unique_ptr<Procedure> procedure_for(const Step& step,
                                         const std::vector<double>& output_intervals = {});

}  // namespace clinch
