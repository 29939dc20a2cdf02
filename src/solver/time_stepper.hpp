// The time policy of a procedure (ARCHITECTURE.md principle 2): given how each attempt ended, the
// next increment to try, or the end of the step, or a stop with its reason. Each step kind has
// its own, made by its procedure (procedure.hpp; static_time_stepper.hpp for *STATIC); the step
// driver runs any of them around the same increment attempt. Pure objects: no deck, no files, no
// solver.
#pragma once

#include <limits>
#include <string>

namespace clinch {

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
  // A converged increment's accuracy measure over its tolerance, ε/T (the half-increment
  // residual of *DYNAMIC: procedure.hpp, IncrementAccuracy); NaN when the step measures none.
  double accuracy = std::numeric_limits<double>::quiet_NaN();
};

struct TimeProposal {
  enum class Kind {
    Attempt,  // try an increment of `dt` (after a cutback when `cut_back`)
    Done,     // the step has reached its period
    Stop,     // the step cannot go on, because of `reason`
    // The increment of `dt` cannot be solved as one: follow the equilibrium path inside it
    // (increment_path.hpp) and report the outcome to next(); if that fails too, stop for
    // `reason`.
    FollowPath,
  };
  Kind kind = Kind::Attempt;
  double dt = 0.0;
  bool cut_back = false;
  std::string reason;
};

class TimeStepper {
 public:
  virtual ~TimeStepper() = default;
  virtual TimeProposal first() = 0;
  virtual TimeProposal next(const AttemptOutcome& outcome) = 0;
  virtual double step_time() const = 0;  // at the end of the last accepted increment
  virtual int increments() const = 0;    // accepted so far
  virtual int cutbacks() const = 0;      // in the whole step
  // Is the increment of the last accepted attempt the step's last one?
  virtual bool at_end() const = 0;
};

}  // namespace clinch
