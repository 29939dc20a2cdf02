#include "src/solver/arc_length_stepper.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string_view>

namespace clinch {
namespace {

// The arc length is the step's "time", without an end of its own: the step ends on its criteria
// or after INC increments, which this stepper counts before the static one would stop.
StaticTimeSettings arc_settings(const StaticProcedure& procedure, int max_increments,
                                const TimeIncrementationControls& controls) {
  const RiksSettings& r = *procedure.riks;
  StaticTimeSettings s;
  s.period = std::numeric_limits<double>::infinity();
  s.initial_increment = r.initial_arc;
  s.min_increment = r.min_arc;
  s.max_increment = r.max_arc.value_or(std::numeric_limits<double>::infinity());
  s.direct = procedure.direct;
  s.max_increments = max_increments + 1;
  s.controls = controls;
  return s;
}

}  // namespace

ArcLengthStepper::ArcLengthStepper(const StaticProcedure& procedure, int max_increments,
                                   const TimeIncrementationControls& controls,
                                   ArcLengthProblem& path, const StepProblem& step)
    : arc_(arc_settings(procedure, max_increments, controls)),
      settings_(*procedure.riks),
      max_increments_(max_increments),
      path_(path),
      step_(step) {}

TimeProposal ArcLengthStepper::first() {
  if (settings_.resolved_node >= 0) {
    monitored_ = step_.nodal_value(settings_.resolved_node, settings_.dof);
  }
  const TimeProposal proposal = arc_.first();
  last_arc_ = proposal.dt;
  return proposal;
}

TimeProposal ArcLengthStepper::next(const AttemptOutcome& outcome) {
  const bool failed = outcome.kind == AttemptOutcome::Kind::NotConverged ||
                      outcome.kind == AttemptOutcome::Kind::Diverged ||
                      outcome.kind == AttemptOutcome::Kind::EvaluationFailed;
  // A failed arc length is tried again with the load falling and with a displacement held before
  // it is cut back (ArcLengthProblem::reversing, holding): the path may turn at a limit point on
  // a law's kink.
  if (failed && path_.attempt_failed()) {
    return {TimeProposal::Kind::Attempt, last_arc_, true, {}};
  }
  TimeProposal proposal = arc_.next(outcome);
  last_arc_ = proposal.dt;
  // The static stepper's "time increment" is this step's arc length.
  constexpr std::string_view kTime = "time increment ";
  if (proposal.kind == TimeProposal::Kind::Stop && proposal.reason.starts_with(kTime)) {
    proposal.reason.replace(0, kTime.size(), "arc length ");
  }
  if (outcome.kind != AttemptOutcome::Kind::Converged) return proposal;
  path_.commit();
  ended_ = stopping_criterion();
  if (!ended_.empty()) return {TimeProposal::Kind::Done, 0.0, false, {}};
  return proposal;
}

std::string ArcLengthStepper::stopping_criterion() {
  const double lpf = path_.load_factor();
  if (settings_.max_lpf && lpf >= *settings_.max_lpf) {
    return fmt::format("the LPF {:.6g} reached the maximum LPF {:.6g} of the data line", lpf,
                       *settings_.max_lpf);
  }
  if (settings_.resolved_node >= 0) {
    const double before = monitored_;
    monitored_ = step_.nodal_value(settings_.resolved_node, settings_.dof);
    const double target = settings_.displacement;
    if (before != target && (before - target) * (monitored_ - target) <= 0) {
      return fmt::format("DOF {} of the monitored node crossed {:.6g} (it is {:.6g}; LPF {:.6g})",
                         settings_.dof, target, monitored_, lpf);
    }
  }
  if (arc_.increments() >= max_increments_) {
    return fmt::format(
        "the step reached its {} increments (INC) without a stopping criterion "
        "of its data line (LPF {:.6g})",
        max_increments_, lpf);
  }
  return {};
}

}  // namespace clinch
