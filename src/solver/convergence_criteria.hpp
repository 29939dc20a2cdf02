// The equilibrium tests of *CONTROLS, PARAMETERS=FIELD (keywords.md §16): residual against the
// time-averaged force q̄, correction against the increment of the solution, the linear-increment
// and zero-force shortcuts, and clinch's constraint-violation test. Newton asks it one question
// per iteration; the step driver keeps q̄ up to date across increments. q̃ is the problem's
// (IterationNorms::flux): the mean of its force entries, element by element, so that forces that
// cancel at a node still count (ForceEntries, docs/decisions.md).
#pragma once

#include "src/model/history_model.hpp"
#include "src/solver/nonlinear_problem.hpp"

namespace clinch {

class ConvergenceCriteria {
 public:
  explicit ConvergenceCriteria(const Controls& controls) : controls_(controls) {}

  // A new step: q̄ restarts from the last value (q̄₀ before any increment).
  void start_step(const Controls& controls);
  // The increment converged with these norms: they join the time average of q̄.
  void accept_increment(const IterationNorms& norms);

  // `iteration` counts the corrections made so far (0: the start of the increment, which passes
  // only the ε_l test); after I_P iterations Rₚ replaces Rₙ.
  bool converged(const IterationNorms& norms, int iteration) const;
  // q̄ of field f including the current iteration's flux.
  double average_flux(const IterationNorms& norms, int field) const;

 private:
  const FieldControls& field(int f) const { return f == 0 ? controls_.translation : controls_.rotation; }
  // q̄ of the converged increments of field f (q̄₀ before any carried force).
  double time_average(int f) const;
  bool carries_force(const IterationNorms& norms, int f) const;
  Controls controls_;
  double flux_sum_[2] = {0, 0};
  int flux_count_[2] = {0, 0};
};

}  // namespace clinch
