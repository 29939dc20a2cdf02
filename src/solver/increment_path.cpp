#include "src/solver/increment_path.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "src/solver/arc_length_problem.hpp"
#include "src/solver/arc_length_stepper.hpp"
#include "src/solver/bordered_solver.hpp"

namespace clinch {
namespace {

// The path's arc lengths in units of the increment (a linear response covers Δλ = Δl), and at
// most this many points before the increment's end.
constexpr double kInitialArc = 0.25, kMinArc = 1e-4, kMaxArc = 0.5;
constexpr int kMaxPoints = 200;

}  // namespace

IncrementPathResult follow_increment_path(NonlinearProblem& problem, StepProblem& step,
                                          LinearSolver& solver, const IncrementSpan& span,
                                          const TimeIncrementationControls& controls,
                                          const IncrementSolve& solve) {
  const auto time_at = [&span](double lpf) { return span.step_time + lpf * span.dt; };
  const double from = span.step_time, to = span.step_time + span.dt;
  ArcLengthProblem path(
      problem, [&](double lpf) { step.set_increment_fraction(from, to, lpf); }, true);
  BorderedSolver bordered(solver, path);
  path.begin_step();
  StaticProcedure arcs;
  arcs.riks = RiksSettings{};
  arcs.riks->initial_arc = kInitialArc;
  arcs.riks->min_arc = kMinArc;
  arcs.riks->max_arc = kMaxArc;
  ArcLengthStepper stepper(arcs, kMaxPoints, controls, path, step);
  IncrementPathResult result;
  for (TimeProposal proposal = stepper.first();;) {
    if (proposal.kind != TimeProposal::Kind::Attempt) {
      result.reason =
          proposal.kind == TimeProposal::Kind::Stop
              ? proposal.reason
              : fmt::format("{} points without reaching the increment's end", kMaxPoints);
      return result;
    }
    path.begin_increment(proposal.dt);
    const double start = path.load_factor();  // the last point's
    step.begin_increment(time_at(start), span.total_time + (time_at(start) - span.step_time),
                         proposal.dt * span.dt, 0.0);
    PathPoint attempt = solve(path, bordered);
    result.last = attempt.report;
    AttemptOutcome outcome = attempt.outcome;
    if (span.loads_change && outcome.kind == AttemptOutcome::Kind::Converged &&
        path.load_factor() < start) {
      // Under a load the path turned back: a limit point, past which the far equilibrium is
      // reached only by a jump.
      result.reason = "the load passes a limit point inside it";
      result.note = step.failure_note(-1);
      step.revert();
      return result;
    }
    if (outcome.kind == AttemptOutcome::Kind::Converged && path.load_factor() >= 1.0) {
      // Past the end: the end itself, directly from the last point.
      step.revert();
      step.begin_increment(to, span.total_time + span.dt, (1.0 - start) * span.dt, 0.0);
      attempt = solve(problem, solver);
      result.last = attempt.report;
      outcome = attempt.outcome;
      if (outcome.kind == AttemptOutcome::Kind::Converged) {
        result.converged = true;
        return result;
      }
      if (outcome.kind == AttemptOutcome::Kind::LawAsksSmaller) {
        outcome.kind = AttemptOutcome::Kind::NotConverged;
      }
    }
    proposal = stepper.next(outcome);
    if (outcome.kind == AttemptOutcome::Kind::Converged) {
      step.commit();
      ++result.points;
      result.lowest = std::min(result.lowest, path.load_factor());
    } else {
      step.revert();
    }
  }
}

}  // namespace clinch
