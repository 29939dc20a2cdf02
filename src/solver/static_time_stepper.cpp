#include "src/solver/static_time_stepper.hpp"

#include <fmt/format.h>

#include <algorithm>

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
                                          const TimeIncrementationControls& controls) {
  return {procedure.period,
          procedure.initial_increment,
          procedure.min_increment,
          procedure.max_increment,
          procedure.direct,
          max_increments,
          controls,
          std::nullopt};
}

StaticTimeStepper::StaticTimeStepper(const StaticTimeSettings& settings)
    : settings_(settings), dt_(std::min(settings.initial_increment, settings.period)) {}

TimeProposal StaticTimeStepper::first() { return propose(); }

TimeProposal StaticTimeStepper::next(const AttemptOutcome& outcome) {
  if (outcome.kind != AttemptOutcome::Kind::Converged) return cut_back(outcome);
  step_time_ += dt_;
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
  // The last increment ends exactly at T (keywords.md §15).
  const double remaining = settings_.period - step_time_;
  if (dt_ >= remaining * (1.0 - 1e-9)) dt_ = remaining;
  return proposal(TimeProposal::Kind::Attempt, dt_);
}

TimeProposal StaticTimeStepper::stop(std::string reason) const {
  return proposal(TimeProposal::Kind::Stop, dt_, false, std::move(reason));
}

TimeProposal StaticTimeStepper::give_up(const AttemptOutcome& outcome, std::string why) const {
  std::string stated = outcome.reason_stands ? outcome.reason : std::move(why);
  if (!outcome.note.empty()) stated += "; " + outcome.note;
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
  dt_ *= smaller ? outcome.dt_ratio : outcome.kind == Kind::Diverged ? t.df : t.dc;
  easy_in_a_row_ = 0;
  accurate_in_a_row_ = 0;
  if (dt_ < settings_.min_increment * (1.0 - 1e-12)) {
    return give_up(outcome, fmt::format("time increment {} below the minimum {} ({})", dt_,
                                        settings_.min_increment, outcome.reason));
  }
  return proposal(TimeProposal::Kind::Attempt, dt_, true);
}

}  // namespace clinch
