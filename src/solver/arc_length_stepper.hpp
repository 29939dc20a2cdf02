// The increment policy of a Riks step (docs/riks.md): arc lengths grow and are cut back as the
// increments of *STATIC are (static_time_stepper.hpp, with the arc length as the step's "time",
// between Δl_min and Δl_max), and the step ends after the first converged increment that meets a
// stopping criterion of its data line: the LPF reaches λ_end, or the monitored DOF crosses its
// value; otherwise after INC increments. Each converged increment becomes the start of the next
// in the path (ArcLengthProblem::commit).
#pragma once

#include <string>

#include "src/solver/arc_length_problem.hpp"
#include "src/solver/static_time_stepper.hpp"

namespace clinch {

class ArcLengthStepper final : public TimeStepper {
 public:
  ArcLengthStepper(const StaticProcedure& procedure, int max_increments,
                   const TimeIncrementationControls& controls, ArcLengthProblem& path,
                   const StepProblem& step);

  TimeProposal first() override;
  TimeProposal next(const AttemptOutcome& outcome) override;
  double step_time() const override { return arc_.step_time(); }
  int increments() const override { return arc_.increments(); }
  int cutbacks() const override { return arc_.cutbacks(); }
  bool at_end() const override { return !ended_.empty(); }
  // Why the step ended (empty while it goes on).
  const std::string& end_reason() const { return ended_; }

 private:
  std::string stopping_criterion();

  StaticTimeStepper arc_;
  const RiksSettings& settings_;
  int max_increments_;
  ArcLengthProblem& path_;
  const StepProblem& step_;
  double monitored_ = 0.0;  // the monitored DOF's value at the last converged increment
  double last_arc_ = 0.0;   // of the last attempt proposed
  std::string ended_;
};

}  // namespace clinch
