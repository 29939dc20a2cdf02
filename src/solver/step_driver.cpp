#include "src/solver/step_driver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "src/solver/convergence_criteria.hpp"
#include "src/solver/frequency_step.hpp"
#include "src/solver/increment_path.hpp"
#include "src/solver/procedure.hpp"
#include "src/solver/static_perturbation_step.hpp"

namespace clinch {
namespace {

// What an attempt leaves for the stepper and for the acceptance of its increment.
struct Attempted {
  AttemptOutcome outcome;
  IncrementAttempt status_line;
  StepRequest request;
  IterationNorms last_iteration;  // the converged iteration's norms (keywords.md §16)
  IncrementAccuracy accuracy;     // the procedure's measure of the converged increment
};

class Driver {
 public:
  Driver(const Model& model, NonlinearProblem& problem, StepProblem& step_problem,
         const SolverFactory& solvers, RunOutputs& out, const RunOptions& options)
      : model_(model),
        problem_(problem),
        step_problem_(step_problem),
        solvers_(solvers),
        out_(out),
        options_(options),
        criteria_(model.history.steps.empty() ? Controls{} : model.history.steps[0].controls) {}

  RunResult run() {
    // Row 0: the initial state, before any condition applies (output-variables.md §1.4).
    Eigen::VectorXd residual(problem_.size());
    if (const EvalStatus initial = problem_.evaluate(residual, nullptr); !initial.ok) {
      fail(initial.message, 1, 0);
      out_.stopped(result_.reason, result_.step, result_.increment, result_.time, true);
      return result_;
    }
    out_.initial_state();
    if (!outputs_written(1, 0)) return stop();
    for (std::size_t s = 0; s < model_.history.steps.size(); ++s) {
      if (!run_step(s)) return stop();
    }
    if (!out_.completed() && !outputs_written(result_.step, result_.increment)) return stop();
    result_.completed = true;
    return result_;
  }

 private:
  RunResult stop() {
    out_.stopped(result_.reason, result_.step, result_.increment, result_.time, false);
    return result_;
  }

  // Between attempts, or when Newton stopped an attempt for it, the history holds every converged
  // increment and nothing more, so a stop asked from outside (SIGINT, SIGTERM) is honoured here.
  bool interrupted(int step, int increment) {
    const char* signal = options_.stop_requested ? options_.stop_requested() : nullptr;
    if (signal == nullptr) return false;
    fail(fmt::format("interrupted by {}", signal), step, increment);
    return true;
  }

  // False, with the file and its error as the reason, once any output failed to be written: the
  // run stops there rather than go on with a history that has lost rows. While all is well it
  // records how far the run got, which a failed COMPLETED line reports.
  bool outputs_written(int step, int increment) {
    if (const OutputFile* file = out_.failed_file()) {
      result_.io_error = true;
      return fail(file->error(), step, increment);
    }
    result_.step = step;
    result_.increment = increment;
    return true;
  }

  bool fail(std::string reason, int step, int increment) {
    result_.reason = std::move(reason);
    result_.step = step;
    result_.increment = increment;
    result_.time = total_time_;
    return false;
  }

  // One attempt: Newton, then the stop active set (behaviors.md §5.1), re-solved until it settles;
  // on the step's system, or on `problem` and `solver` (a point inside an increment:
  // increment_path.hpp).
  NewtonReport attempt(int step, int increment, int attempt_number, int& iterations, int& changes,
                       NonlinearProblem* problem = nullptr, LinearSolver* solver = nullptr) {
    const TimeIncrementationControls& t = controls_->time;
    const NewtonOptions options{t.ic,
                                t.i0,
                                rules_.accept_unconverged,
                                line_search_,
                                options_.stop_requested,
                                rules_.fixed_increments};
    iterations = 0;
    changes = 0;
    for (;;) {
      const auto start = std::chrono::steady_clock::now();
      NewtonReport report = solve_increment(problem ? *problem : *newton_problem_,
                                            solver ? *solver : *newton_solver_, criteria_, options);
      result_.newton_seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      result_.linear_seconds += report.linear_seconds;
      result_.factorizations += report.factorizations;
      for (std::size_t i = 0; i < report.iterations.size(); ++i) {
        const IterationNorms& n = report.iterations[i];
        IterationRecord record;
        record.step = step;
        record.increment = increment;
        record.attempt = attempt_number;
        record.iteration = iterations + static_cast<int>(i);
        record.residual_norm = n.residual_norm;
        record.largest_residual = std::max(n.largest_residual[0], n.largest_residual[1]);
        record.correction_norm = n.correction_norm;
        record.largest_correction = std::max(n.largest_correction[0], n.largest_correction[1]);
        record.constraint_violation = n.constraint_violation;
        out_.iteration(record);
      }
      iterations += std::max(0, static_cast<int>(report.iterations.size()) - 1);
      if (!report.converged() || !step_problem_.update_active_set()) return report;
      if (++changes > 8) {
        report.outcome = NewtonOutcome::TooManyIterations;
        report.message = "stop active set did not settle";
        return report;
      }
    }
  }

  bool run_step(std::size_t s) {
    const Step& step = model_.history.steps[s];
    if (step.frequency) return run_frequency_step(s);
    if (step.perturbation) return run_static_perturbation_step(s);
    const std::unique_ptr<Procedure> procedure =
        procedure_for(step, output_time_intervals(model_.history, s));
    const int step_number = static_cast<int>(s) + 1;
    if (!begin_step(step, *procedure, step_number)) return false;
    newton_problem_ = &procedure->newton_problem(problem_, step_problem_);
    newton_solver_ = &procedure->newton_solver(*solver_);
    const std::unique_ptr<TimeStepper> time_stepper = procedure->time_stepper();
    TimeStepper& stepper = *time_stepper;
    Attempted last;
    const int cutbacks_before = result_.cutbacks;
    int attempt_number = 0;
    for (TimeProposal proposal = stepper.first(); proposal.kind != TimeProposal::Kind::Done;) {
      const int increment = stepper.increments() + 1;
      if (proposal.kind == TimeProposal::Kind::Stop) {
        return fail(proposal.reason, step_number, increment);
      }
      if (proposal.kind == TimeProposal::Kind::FollowPath) {
        ++attempt_number;
        if (!follow_path(step_number, increment, attempt_number, proposal, last)) {
          return false;
        }
        proposal = stepper.next(last.outcome);
        result_.cutbacks = cutbacks_before + stepper.cutbacks();
        if (!accept_increment(step_number, stepper, last)) return false;
        continue;
      }
      if (proposal.cut_back) {
        out_.cut_back(step_number, increment, last.outcome.reason, proposal.dt);
      }
      attempt_number = proposal.cut_back ? attempt_number + 1 : 1;
      if (!attempt_increment(*procedure, step_number, increment, attempt_number, proposal.dt,
                             last)) {
        return false;
      }
      const bool converged = last.outcome.kind == AttemptOutcome::Kind::Converged;
      proposal = stepper.next(last.outcome);
      result_.cutbacks = cutbacks_before + stepper.cutbacks();
      if (converged && !accept_increment(step_number, stepper, last)) return false;
    }
    if (const std::string why = procedure->end_reason(); !why.empty()) {
      out_.step_ended(step_number, why);
    }
    step_problem_.end_step(procedure->period(), total_time_);
    for (const std::string& line : step_problem_.step_summary()) {
      out_.note(step_number, 0, line);
    }
    return true;
  }

  // A *FREQUENCY step (frequency_step.hpp): the conditions of the base state at an increment of
  // no length from the converged state, the symmetric tangent there, and back to that state. It
  // takes no time and writes no history row; the next step starts from the same base state.
  bool run_frequency_step(std::size_t s) {
    const Step& step = model_.history.steps[s];
    const int step_number = static_cast<int>(s) + 1;
    if (interrupted(step_number, 0)) return false;
    out_.begin_step(s);
    step_problem_.begin_step(s, step.nlgeom);
    step_problem_.use_storage(true);
    std::unique_ptr<LinearSolver> solver = solvers_(true, false);
    if (!solver) {
      return fail("the requested linear solver cannot solve a *FREQUENCY step", step_number, 0);
    }
    std::string error;
    if (solver->analyze(problem_.pattern(), &error) != LinearStatus::Ok) {
      return fail(fmt::format("linear solver analysis failed: {}", error), step_number, 0);
    }
    step_problem_.begin_increment(0.0, total_time_, 0.0, 0.0);
    const FrequencyModel model = step_problem_.frequency_model();
    out_.note(step_number, 0,
              fmt::format("{} on the upper triangle ({} equations): the symmetric tangent of the "
                          "base state and the lumped mass ({} directions with inertia)",
                          solver->name(), problem_.pattern().n, model.mass.factor.size()));
    FrequencyStepResult result = solve_frequency_step(*step.frequency, problem_, model, *solver);
    step_problem_.revert();
    step_problem_.end_perturbation_step();
    if (!result.error.empty()) {
      NewtonReport report;
      report.outcome = NewtonOutcome::SolverFailed;
      report.message = result.error;
      report.failed_equation = result.failed_equation;
      // A massless DOF without stiffness (a mechanism of the massless part) leaves K − σM
      // singular at every shift: named as Newton's singular systems are.
      return fail(result.failed_equation >= 0
                      ? fmt::format("{}; {}", result.error, step_problem_.describe_failure(report))
                      : result.error,
                  step_number, 0);
    }
    for (const std::string& line : result.notes) out_.note(step_number, 0, line);
    if (std::string written = out_.modes_extracted(step_number, result.modes, model.dof_names);
        !written.empty()) {
      result_.io_error = true;
      return fail(std::move(written), step_number, 0);
    }
    return outputs_written(step_number, 0);
  }

  // A *STATIC step of a *STEP, PERTURBATION (static_perturbation_step.hpp): the linear response
  // about the base state, one history row of it, and back to the base state, which the next step
  // continues from. It takes no time. Its row holds each column's derivative along the response,
  // (y(+h) − y(−h))/2h at τ = ±h of it: exact for what is linear in the state (U, and every
  // column of linear laws), within O(h²) otherwise (docs/perturbation.md).
  bool run_static_perturbation_step(std::size_t s) {
    constexpr double h = 1e-4;
    const Step& step = model_.history.steps[s];
    const int step_number = static_cast<int>(s) + 1;
    if (interrupted(step_number, 0)) return false;
    out_.begin_step(s);
    step_problem_.begin_step(s, step.nlgeom);
    if (!choose_storage(step, step_number)) return false;
    const PerturbationSolution solution =
        solve_static_perturbation(problem_, step_problem_, *solver_, total_time_);
    std::string error = solution.error;
    if (error.empty()) {
      out_.note(step_number, 0,
                "linear perturbation about the base state: the tangent there, the step's loads "
                "and prescribed values as perturbations");
      const bool written = out_.perturbation_response(step_number, total_time_, h, [&](double tau) {
        return evaluate_perturbed_state(problem_, step_problem_, solution.response, tau,
                                        total_time_, error);
      });
      if (!written && error.empty()) error = "the perturbation response could not be evaluated";
    } else if (solution.failed_equation >= 0) {
      NewtonReport report;
      report.outcome = NewtonOutcome::SolverFailed;
      report.message = error;
      report.failed_equation = solution.failed_equation;
      error = fmt::format("{}; {}", error, step_problem_.describe_failure(report));
    }
    step_problem_.revert();
    step_problem_.end_perturbation_step();
    if (!error.empty()) return fail(error, step_number, 1);
    return outputs_written(step_number, 1);
  }

  // What the step sets once: NLGEOM, the storage and its solver, the conditions, the line search,
  // the criteria and the output columns.
  bool begin_step(const Step& step, const Procedure& procedure, int step_number) {
    controls_ = &step.controls;
    rules_ = procedure.increment_rules();
    out_.begin_step(static_cast<std::size_t>(step_number - 1));  // its name first in the log
    step_problem_.begin_step(static_cast<std::size_t>(step_number - 1), step.nlgeom);
    if (!choose_storage(step, step_number)) return false;
    warned_.clear();
    // A law may ask for a line search (friction: docs/decisions.md "Friction"); the deck's own
    // PARAMETERS=LINE SEARCH wins.
    const ProcedureNeeds needs = step_problem_.procedure_needs();
    line_search_ = step.controls.line_search;
    if (needs.line_search_iterations > 0 && !line_search_.given &&
        line_search_.max_iterations == 0) {
      line_search_.max_iterations = needs.line_search_iterations;
      out_.note(step_number, 0,
                fmt::format("line search on (N_ls = {}): {} and the deck does not set *CONTROLS, "
                            "PARAMETERS=LINE SEARCH",
                            needs.line_search_iterations, needs.line_search_reason));
    }
    for (const std::string& note : needs.notes) {
      out_.note(step_number, 0, note);
    }
    criteria_.start_step(step.controls);
    step_time_ = 0.0;
    return true;
  }

  // One attempt at the increment from step_time_ to step_time_ + dt: conditions, predictor,
  // Newton with the stop active set, and the failure criteria of the converged state, which
  // release components and solve the same increment again (behaviors.md §5.3). A failed or
  // abandoned attempt is reverted and its status line written. False when the run must stop
  // here (a signal, an output that cannot be written).
  bool attempt_increment(const Procedure& procedure, int step_number, int increment,
                         int& attempt_number, double dt, Attempted& attempted) {
    for (;; ++attempt_number) {
      if (interrupted(step_number, increment)) return false;
      const double new_time = step_time_ + dt;
      procedure.begin_increment(
          step_problem_, {new_time, total_time_ + dt, dt, increment > 1 ? previous_dt_ : 0.0});
      if (options_.check_tangent) {
        out_.note(step_problem_.check_tangent(step_number, increment));
      }
      int iterations = 0, changes = 0;
      const NewtonReport report =
          attempt(step_number, increment, attempt_number, iterations, changes);
      result_.iterations += iterations;
      note_solver_hand_over(step_number, increment);
      if (report.outcome == NewtonOutcome::Interrupted && interrupted(step_number, increment)) {
        return false;
      }
      const bool converged = report.converged();
      // A converged attempt is still abandoned when a law asks for a smaller increment.
      attempted.request = step_problem_.step_request();
      bool smaller = converged && attempted.request.dt_ratio < 1.0;
      attempted.status_line = {step_number,           increment,  attempt_number,
                               !converged || smaller, iterations, iterations + changes,
                               total_time_ + dt,      new_time,   dt};
      if (converged && !smaller && redo_after_failures(step_number, increment, attempted)) continue;
      // ... or when the procedure finds it inaccurate (a dynamic step's half-increment residual).
      attempted.accuracy = {};
      if (converged && !smaller) {
        const IterationNorms& norms = report.iterations.back();
        const double force = criteria_.average_flux(norms, 0);
        attempted.accuracy =
            procedure.check_increment(step_problem_, {new_time, total_time_ + dt, dt, 0.0},
                                      force > 0.0 ? force : criteria_.average_flux(norms, 1));
        if (attempted.accuracy.ratio < 1.0) {
          smaller = true;
          attempted.request.dt_ratio = attempted.accuracy.ratio;
          attempted.request.unreliable = false;
          attempted.request.message = attempted.accuracy.message;
          attempted.status_line.cut_back = true;
        }
      }
      if (!converged || smaller) out_.attempt_ended(attempted.status_line);
      if (!outputs_written(step_number, increment)) return false;
      attempted.outcome = outcome_of(report, attempted.request, smaller, iterations);
      attempted.outcome.accuracy = attempted.accuracy.accuracy;
      if (converged && !smaller) {
        attempted.last_iteration = report.iterations.back();
      } else {
        step_problem_.revert();
        if (!converged) step_problem_.attempt_failed();
      }
      return true;
    }
  }

  // No increment converges at this point: the path inside the first one tried here is followed
  // to its end (increment_path.hpp), which becomes the increment. False when that fails too
  // (the run stops for the stepper's reason) or the run must stop here.
  bool follow_path(int step_number, int increment, int attempt_number, const TimeProposal& proposal,
                   Attempted& attempted) {
    if (interrupted(step_number, increment)) return false;
    const double dt = proposal.dt;
    int iterations = 0;
    const IncrementSolve solve = [&](NonlinearProblem& problem, LinearSolver& solver) {
      int its = 0, changes = 0;
      PathPoint point;
      point.report =
          attempt(step_number, increment, attempt_number, its, changes, &problem, &solver);
      iterations += its;
      const StepRequest request = step_problem_.step_request();
      point.outcome = outcome_of(point.report, request,
                                 point.report.converged() && request.dt_ratio < 1.0, its);
      return point;
    };
    const IncrementPathResult path = follow_increment_path(
        problem_, step_problem_, *solver_,
        {step_time_, total_time_, dt, step_problem_.loads_change(step_time_, step_time_ + dt)},
        controls_->time, solve);
    result_.iterations += iterations;
    note_solver_hand_over(step_number, increment);
    if (!path.converged) {
      step_problem_.revert();
      // The limit-point note once: the stepper's reason may have it already.
      const bool noted =
          path.note.empty() || proposal.reason.find("a limit point") != std::string::npos;
      return fail(fmt::format("{}; following the path inside the increment did not reach its "
                              "end either ({}{})",
                              proposal.reason, path.reason, noted ? "" : ": " + path.note),
                  step_number, increment);
    }
    out_.note(step_number, increment,
              fmt::format("no increment converged here ({}): the path inside an increment of {} "
                          "was followed to its end through {} points, its values going back as "
                          "far as {:.3g} of it",
                          proposal.reason, dt, path.points, path.lowest));
    attempted.request = step_problem_.step_request();
    attempted.status_line = {step_number, increment,        attempt_number,  false, iterations,
                             iterations,  total_time_ + dt, step_time_ + dt, dt};
    attempted.accuracy = {};
    attempted.outcome = {};
    attempted.outcome.iterations = iterations;
    attempted.last_iteration = path.last.iterations.back();
    return true;
  }

  // §5.3: a failure criterion met on the converged state releases its components; the same
  // increment is then solved again (an attempt of its own, with the same time).
  bool redo_after_failures(int step_number, int increment, const Attempted& attempted) {
    const std::vector<std::string> failures = step_problem_.release_failed_components();
    if (failures.empty()) return false;
    for (const std::string& f : failures) {
      out_.note(step_number, increment, f + "; the increment is solved again");
    }
    IncrementAttempt redone = attempted.status_line;
    redone.cut_back = true;
    out_.attempt_ended(redone);
    step_problem_.revert();
    return true;
  }

  // The stepper's view of an attempt. A singular system names its DOF, which stands as the reason
  // when no smaller increment helps; the state may add a note (a connector deleted next to it).
  AttemptOutcome outcome_of(const NewtonReport& report, const StepRequest& request, bool smaller,
                            int iterations) const {
    using Kind = AttemptOutcome::Kind;
    AttemptOutcome outcome;
    outcome.iterations = iterations;
    outcome.dt_ratio = request.dt_ratio;
    outcome.unreliable = request.unreliable;
    if (smaller) {
      outcome.kind = Kind::LawAsksSmaller;
      outcome.reason = request.message;
      return outcome;
    }
    if (report.converged()) return outcome;
    outcome.kind = report.outcome == NewtonOutcome::Diverged           ? Kind::Diverged
                   : report.outcome == NewtonOutcome::EvaluationFailed ? Kind::EvaluationFailed
                                                                       : Kind::NotConverged;
    outcome.note = step_problem_.failure_note(report.failed_equation);
    outcome.reason_stands = report.outcome == NewtonOutcome::SolverFailed;
    outcome.reason = outcome.reason_stands || report.outcome == NewtonOutcome::NonFinite
                         ? step_problem_.describe_failure(report)
                         : report.message;
    return outcome;
  }

  // A converged increment: commit, tell the outputs (its row, then its status line:
  // run_outputs.hpp), engage locks and report the events.
  bool accept_increment(int step_number, const TimeStepper& stepper, const Attempted& attempted) {
    const int increment = stepper.increments();
    const double dt = attempted.status_line.time_increment;
    step_problem_.commit();
    criteria_.accept_increment(attempted.last_iteration);
    for (const StepRequest::Warning& w : attempted.request.warnings) {
      if (warned_.insert(w.element).second) out_.warning(w.message);
    }
    step_time_ = stepper.step_time();
    total_time_ += dt;
    ++result_.increments;
    previous_dt_ = dt;
    if (!attempted.accuracy.message.empty()) {
      out_.note(step_number, increment, attempted.accuracy.message);
    }
    out_.increment_converged(attempted.status_line, stepper.at_end());
    if (!outputs_written(step_number, increment)) return false;
    // A lock engages at the converged state; its row shows the unlocked state
    // (behaviors.md §5.2, example E5).
    step_problem_.end_increment();
    for (const std::string& event : step_problem_.take_events()) {
      out_.note(step_number, increment, event);
    }
    for (const std::string& warning : step_problem_.take_warnings()) {
      out_.warning(fmt::format("step {} increment {}: {}", step_number, increment, warning));
    }
    return true;
  }

  // keywords.md §14, friction.md §4.3: the upper triangle and CHOLMOD when every law is
  // symmetric and the step does not ask for UNSYMM=YES; the full pattern and UMFPACK otherwise.
  // UNSYMM=NO keeps the upper triangle and symmetrises unsymmetric laws. A solver is analysed
  // once per storage and kept for later steps.
  bool choose_storage(const Step& step, int step_number) {
    const bool laws_symmetric = step_problem_.laws_symmetric();
    bool symmetric = laws_symmetric;
    std::string why =
        laws_symmetric ? "every law's tangent is symmetric" : "a law's tangent is unsymmetric";
    if (step.unsymmetric == Unsymmetric::Yes) {
      symmetric = false;
      why = "*STEP, UNSYMM=YES";
    } else if (step.unsymmetric == Unsymmetric::No) {
      symmetric = true;
      why = laws_symmetric ? "*STEP, UNSYMM=NO"
                           : "*STEP, UNSYMM=NO: the unsymmetric tangent is symmetrised";
    }
    std::unique_ptr<LinearSolver>& solver = symmetric ? symmetric_solver_ : full_solver_;
    step_problem_.use_storage(symmetric);
    if (!solver) {
      const auto start = std::chrono::steady_clock::now();
      solver = solvers_(symmetric, step.nlgeom);
      if (!solver) {
        return fail(fmt::format("the requested linear solver cannot solve this step ({}): use "
                                "--solver auto or umfpack",
                                why),
                    step_number, 0);
      }
      std::string error;
      if (solver->analyze(problem_.pattern(), &error) != LinearStatus::Ok) {
        return fail(fmt::format("linear solver analysis failed: {}", error), step_number, 0);
      }
      result_.analyze_seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    solver_ = solver.get();
    if (symmetric && step_problem_.has_multipliers()) why += "; the multipliers make it indefinite";
    if (const std::string choice = solver_->choice(); !choice.empty()) why += "; " + choice;
    announced_solver_ = solver_->name();
    out_.note(step_number, 0,
              fmt::format("{} on the {} ({} equations, {} stored entries): {}", solver_->name(),
                          symmetric ? "upper triangle" : "full pattern",
                          problem_.pattern().summed_size(), problem_.pattern().values.size(), why));
    return true;
  }

  // The automatic choice may hand over between two factorizations (automatic_solver.hpp): the
  // log says so where it happened.
  void note_solver_hand_over(int step_number, int increment) {
    if (solver_ == nullptr || announced_solver_ == solver_->name()) return;
    announced_solver_ = solver_->name();
    out_.note(step_number, increment,
              fmt::format("the linear solver is now {}: {}", announced_solver_, solver_->choice()));
  }

  const Model& model_;
  NonlinearProblem& problem_;  // what Newton solves
  StepProblem& step_problem_;  // the step's set-up, the increment's time, the state between solves
  const SolverFactory& solvers_;
  std::unique_ptr<LinearSolver> symmetric_solver_, full_solver_;
  LinearSolver* solver_ = nullptr;
  std::string announced_solver_;  // the backend the log last named
  // What Newton solves in the current step: problem_ and *solver_, or the procedure's system.
  NonlinearProblem* newton_problem_ = nullptr;
  LinearSolver* newton_solver_ = nullptr;
  RunOutputs& out_;
  const RunOptions& options_;
  ConvergenceCriteria criteria_;
  const Controls* controls_ = nullptr;
  IncrementRules rules_;  // the step's procedure's
  double total_time_ = 0.0;
  double step_time_ = 0.0;    // of the step, at the last converged increment
  double previous_dt_ = 0.0;  // the last converged increment (extrapolation)
  RunResult result_;
  std::set<std::size_t> warned_;    // elements whose law warning this step's log already has
  LineSearchControls line_search_;  // this step's, with what the laws ask for
};

}  // namespace

RunResult run_analysis(const Model& model, NonlinearProblem& problem, StepProblem& step_problem,
                       const SolverFactory& solvers, RunOutputs& outputs,
                       const RunOptions& options) {
  return Driver(model, problem, step_problem, solvers, outputs, options).run();
}

}  // namespace clinch
