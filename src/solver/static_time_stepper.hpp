// The time policy of a *STATIC step (keywords.md §15, §16): which increment to try next, given how
// the last attempt ended. Automatic incrementation grows the increment after easy increments (D_D
// after two in a row with at most I_G iterations), no more than an accuracy measure allows where
// the step has one (AccuracyControls), shrinks it after a hard one (D_B above I_L),
// cuts back a failed attempt (D_F after divergence, D_C otherwise, or the ratio a law asked for)
// at most I_A times in a row and never below the minimum, and caps growth where a law asks; DIRECT
// keeps the increment and stops on the first failure. The last increment ends exactly at the step
// period, and every increment at the output times it would pass.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "src/model/history_model.hpp"
#include "src/solver/time_stepper.hpp"

namespace clinch {

// The control of a step whose increments are also held to an accuracy tolerance T (the
// half-increment residual of *DYNAMIC, docs/dynamics.md "Automatic incrementation"; the Abaqus
// Analysis User's Guide, "Time integration accuracy in transient problems", with its defaults).
// A converged increment with ε > T is solved again with D_A (T/ε) times the increment; after N_S
// increments in a row with ε < D_H T and no cutback, the next grows to D_S (T/ε) times the last,
// at most D_M times; otherwise the accuracy lets it not grow.
struct AccuracyControls {
  int ns = 3;
  double da = 0.85, dh = 0.75, ds = 0.8, dm = 1.25;
};

struct StaticTimeSettings {
  double period = 1.0;             // T
  double initial_increment = 1.0;  // Δt₀
  double min_increment = 1e-5;     // ignored with DIRECT
  double max_increment = 1.0;      // ignored with DIRECT
  bool direct = false;
  int max_increments = 100;  // *STEP, INC
  TimeIncrementationControls controls;
  std::optional<AccuracyControls> accuracy;  // none: the step measures no accuracy
  // Step times between history outputs (TIME INTERVAL, NUMBER INTERVAL; keywords.md §17): an
  // increment that would pass a multiple of one ends there instead, and the next resumes at the
  // increment it was shortened from.
  std::vector<double> output_intervals;
  // Where the step would stop because no increment at this point converges (too many cutbacks,
  // below the minimum, DIRECT), it asks instead to follow the path inside the first increment
  // tried at this point (docs/riks.md "Inside a *STATIC increment").
  bool follow_path_on_stop = false;

  static StaticTimeSettings of(const StaticProcedure& procedure, int max_increments,
                               const TimeIncrementationControls& controls,
                               const std::vector<double>& output_intervals = {});
};

class StaticTimeStepper final : public TimeStepper {
 public:
  explicit StaticTimeStepper(const StaticTimeSettings& settings);

  TimeProposal first() override;
  TimeProposal next(const AttemptOutcome& outcome) override;
  double step_time() const override { return step_time_; }
  int increments() const override { return increments_; }
  int cutbacks() const override { return cutbacks_; }
  bool at_end() const override { return step_time_ >= settings_.period * (1.0 - 1e-12); }

 private:
  TimeProposal propose();
  TimeProposal stop(std::string reason) const;
  TimeProposal give_up(const AttemptOutcome& outcome, std::string why);
  void grow(const AttemptOutcome& outcome);
  TimeProposal cut_back(const AttemptOutcome& outcome);
  double next_output_time() const;

  StaticTimeSettings settings_;
  double dt_ = 0.0, step_time_ = 0.0;
  double attempt_ = 0.0, attempt_end_ = 0.0;  // the increment proposed and the time it ends at
  bool attempt_stretched_ = false;            // it ends exactly at an output time or the period
  // The first increment proposed at the current step time, before any cutback, and whether the
  // last proposal asked to follow its path.
  double first_attempt_ = 0.0, first_end_ = 0.0;
  bool first_stretched_ = false, following_path_ = false;
  double carry_ = 0.0;                        // the rounding the step time's sum carries
  int increments_ = 0, cutbacks_ = 0, cutbacks_in_a_row_ = 0, easy_in_a_row_ = 0;
  int accurate_in_a_row_ = 0;  // increments with ε < D_H T since the last cutback
};

}  // namespace clinch
