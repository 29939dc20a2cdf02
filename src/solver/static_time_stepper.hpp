// The time policy of a *STATIC step (keywords.md §15, §16): which increment to try next, given how
// the last attempt ended. Automatic incrementation grows the increment after easy increments (D_D
// after two in a row with at most I_G iterations), shrinks it after a hard one (D_B above I_L),
// cuts back a failed attempt (D_F after divergence, D_C otherwise, or the ratio a law asked for)
// at most I_A times in a row and never below the minimum, and caps growth where a law asks; DIRECT
// keeps the increment and stops on the first failure. The last increment ends exactly at the step
// period. A pure object: no deck, no files, no solver.
#pragma once

#include <limits>
#include <string>

#include "src/model/history_model.hpp"

namespace clinch {

struct StaticTimeSettings {
  double period = 1.0;             // T
  double initial_increment = 1.0;  // Δt₀
  double min_increment = 1e-5;     // ignored with DIRECT
  double max_increment = 1.0;      // ignored with DIRECT
  bool direct = false;
  int max_increments = 100;  // *STEP, INC
  TimeIncrementationControls controls;

  static StaticTimeSettings of(const StaticProcedure& procedure, int max_increments,
                               const TimeIncrementationControls& controls);
};

// How an attempt at the proposed increment ended, as the step's driver saw it.
struct AttemptOutcome {
  enum class Kind {
    Converged,         // equilibrium found; the laws accept the increment
    LawAsksSmaller,    // converged, but a law asks for a smaller increment (ratio < 1)
    NotConverged,      // Newton failed (iterations, a singular system, a value not finite)
    Diverged,          // Newton's residual grew (keywords.md §16, I₀ rule)
    EvaluationFailed,  // a law or the kinematics could not be evaluated
  };
  Kind kind = Kind::Converged;
  int iterations = 0;  // equilibrium iterations of the attempt
  // The laws' request: at most this ratio of the increment next (none: infinity); `unreliable`
  // keeps it from growing at all.
  double dt_ratio = std::numeric_limits<double>::infinity();
  bool unreliable = false;
  std::string reason;  // why it failed (or what the law asked)
  // A reason that stands as the stop's whole message when no smaller increment helps (a singular
  // system names its DOF better than "too many cutbacks").
  bool reason_stands = false;
  std::string note;  // what the state suggests about a failure (a deleted connector next to it)
};

struct TimeProposal {
  enum class Kind {
    Attempt,  // try an increment of `dt` (after a cutback when `cut_back`)
    Done,     // the step has reached its period
    Stop,     // the step cannot go on, because of `reason`
  };
  Kind kind = Kind::Attempt;
  double dt = 0.0;
  bool cut_back = false;
  std::string reason;
};

class StaticTimeStepper {
 public:
  explicit StaticTimeStepper(const StaticTimeSettings& settings);

  TimeProposal first();
  TimeProposal next(const AttemptOutcome& outcome);

  double step_time() const { return step_time_; }  // at the end of the last accepted increment
  int increments() const { return increments_; }   // accepted so far
  int cutbacks() const { return cutbacks_; }       // in the whole step
  // Is the increment of the last accepted attempt the step's last one?
  bool at_end() const { return step_time_ >= settings_.period * (1.0 - 1e-12); }

 private:
  TimeProposal propose();
  TimeProposal stop(std::string reason) const;
  TimeProposal give_up(const AttemptOutcome& outcome, std::string why) const;
  void grow(const AttemptOutcome& outcome);
  TimeProposal cut_back(const AttemptOutcome& outcome);

  StaticTimeSettings settings_;
  double dt_ = 0.0, step_time_ = 0.0;
  int increments_ = 0, cutbacks_ = 0, cutbacks_in_a_row_ = 0, easy_in_a_row_ = 0;
};

}  // namespace clinch
