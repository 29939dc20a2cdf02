#include "src/solver/static_time_stepper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace clinch {
namespace {

TimeProposal proposal(TimeProposal::Kind kind, double dt, bool cut_back = false,
                      std::string reason = {}) {
  TimeProposal p;
  p.kind = kind;
  p.dt = dt;
  p.cut_back = cut_back;
  p.reason = std::move(reason);
  return p;
}

}  // namespace

StaticTimeSettings StaticTimeSettings::of(const StaticProcedure& procedure, int max_increments,
                                          const TimeIncrementationControls& controls,
                                          const std::vector<double>& output_intervals) {
  return {procedure.period,
          procedure.initial_increment,
          procedure.min_increment,
          procedure.max_increment,
          procedure.direct,
          max_increments,
          controls,
          std::nullopt,
          output_intervals};
}

StaticTimeStepper::StaticTimeStepper(const StaticTimeSettings& settings)
    : settings_(settings), dt_(std::min(settings.initial_increment, settings.period)) {}

TimeProposal StaticTimeStepper::first() { return propose(); }

TimeProposal StaticTimeStepper::next(const AttemptOutcome& outcome) {
  if (following_path_) {
    // The path was followed to the end of the first increment tried here.
    following_path_ = false;
    dt_ = first_attempt_;  // the cutbacks before it do not hold the increments after it back
    attempt_ = first_attempt_;
    attempt_end_ = first_end_;
    attempt_stretched_ = first_stretched_;
  }
  if (outcome.kind != AttemptOutcome::Kind::Converged) return cut_back(outcome);
  if (attempt_stretched_) {
    step_time_ = attempt_end_;
    carry_ = 0.0;
  } else {
    // Compensated (Kahan) sum: 10⁷ fixed increments stay within rounding of k·Δt, so that the
    // output times and the period are met without a sliver increment.
    const double y = attempt_ - carry_;
    const double t = step_time_ + y;
    carry_ = (t - step_time_) - y;
    step_time_ = t;
  }
  ++increments_;
  cutbacks_in_a_row_ = 0;
  if (!settings_.direct) grow(outcome);
  return propose();
}

TimeProposal StaticTimeStepper::propose() {
  if (at_end()) return proposal(TimeProposal::Kind::Done, 0.0);
  if (increments_ >= settings_.max_increments) {
    return stop(fmt::format("too many increments (INC={})", settings_.max_increments));
  }
  // The last increment ends exactly at T (keywords.md §15), and an increment at the output time
  // it would pass (§17). One that would end within 10⁻⁶ of itself short of them is stretched to
  // them: the rounding of a sum of fixed increments leaves no sliver.
  attempt_ = dt_;
  attempt_end_ = step_time_ + dt_;
  const double end = std::min(settings_.period, next_output_time());
  attempt_stretched_ = end - attempt_end_ <= 1e-6 * dt_;
  if (attempt_stretched_) {
    attempt_ = end - step_time_;
    attempt_end_ = end;
  }
  if (cutbacks_in_a_row_ == 0) {
    first_attempt_ = attempt_;
    first_end_ = attempt_end_;
    first_stretched_ = attempt_stretched_;
  }
  return proposal(TimeProposal::Kind::Attempt, attempt_);
}

// The first multiple of an output interval after the step time (infinity: none).
double StaticTimeStepper::next_output_time() const {
  double next = std::numeric_limits<double>::infinity();
  for (const double interval : settings_.output_intervals) {
    next = std::min(next, (std::floor((step_time_ + 1e-6 * dt_) / interval) + 1) * interval);
  }
  return next;
}

TimeProposal StaticTimeStepper::stop(std::string reason) const {
  return proposal(TimeProposal::Kind::Stop, dt_, false, std::move(reason));
}

TimeProposal StaticTimeStepper::give_up(const AttemptOutcome& outcome, std::string why) {
  std::string stated = outcome.reason_stands ? outcome.reason : std::move(why);
  if (!outcome.note.empty()) stated += "; " + outcome.note;
  if (settings_.follow_path_on_stop && !outcome.reason_stands) {
    // Under automatic incrementation the increments before the stop may have shrunk towards
    // the minimum; the path is followed over at least the initial increment, so that its arc
    // lengths measure the motion around the point rather than the last sliver of time.
    following_path_ = true;
    if (!settings_.direct && first_attempt_ < settings_.initial_increment) {
      const double end = std::min(settings_.period, next_output_time());
      first_end_ = std::min(end, step_time_ + settings_.initial_increment);
      first_attempt_ = first_end_ - step_time_;
      first_stretched_ = first_end_ == end;
    }
    return proposal(TimeProposal::Kind::FollowPath, first_attempt_, false, std::move(stated));
  }
  return stop(std::move(stated));
}

// keywords.md §16: D_B after a hard increment, D_D after two easy ones; a law may cap the growth,
// by its ratio, or to none while it doubts its result.
void StaticTimeStepper::grow(const AttemptOutcome& outcome) {
  const TimeIncrementationControls& t = settings_.controls;
  easy_in_a_row_ = outcome.iterations <= t.ig ? easy_in_a_row_ + 1 : 0;
  const double accepted = dt_;
  if (outcome.iterations > t.il) {
    dt_ *= t.db;
  } else if (easy_in_a_row_ >= 2) {
    dt_ *= t.dd;
  }
  dt_ = std::min(
      dt_, accepted * (outcome.unreliable ? std::min(1.0, outcome.dt_ratio) : outcome.dt_ratio));
  if (settings_.accuracy) {
    const AccuracyControls& a = *settings_.accuracy;
    accurate_in_a_row_ = outcome.accuracy < a.dh ? accurate_in_a_row_ + 1 : 0;
    const double allowed =
        accurate_in_a_row_ >= a.ns ? std::min(a.dm, a.ds / outcome.accuracy) : 1.0;
    dt_ = std::min(dt_, accepted * allowed);
  }
  dt_ = std::min(dt_, settings_.max_increment);
}

TimeProposal StaticTimeStepper::cut_back(const AttemptOutcome& outcome) {
  using Kind = AttemptOutcome::Kind;
  const bool smaller = outcome.kind == Kind::LawAsksSmaller;
  if (settings_.direct) {
    if (outcome.kind == Kind::EvaluationFailed) return stop(outcome.reason);
    return give_up(outcome, smaller ? fmt::format("a law asks for a smaller increment than DIRECT "
                                                  "allows ({})",
                                                  outcome.reason)
                                    : fmt::format("no convergence with fixed increments ({})",
                                                  outcome.reason));
  }
  const TimeIncrementationControls& t = settings_.controls;
  ++cutbacks_;
  if (++cutbacks_in_a_row_ > t.ia) {
    return give_up(outcome, fmt::format("too many cutbacks ({}; last: {})", t.ia, outcome.reason));
  }
  dt_ = attempt_ * (smaller ? outcome.dt_ratio : outcome.kind == Kind::Diverged ? t.df : t.dc);
  easy_in_a_row_ = 0;
  accurate_in_a_row_ = 0;
  if (dt_ < settings_.min_increment * (1.0 - 1e-12)) {
    return give_up(outcome, fmt::format("time increment {} below the minimum {} ({})", dt_,
                                        settings_.min_increment, outcome.reason));
  }
  TimeProposal retry = propose();
  retry.cut_back = true;
  return retry;
}

}  // namespace clinch
