#include "src/solver/arc_length_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace clinch {

ArcLengthProblem::ArcLengthProblem(NonlinearProblem& problem, StepProblem& step)
    : ArcLengthProblem(problem, [&step](double lpf) { step.set_load_factor(lpf); }) {}

ArcLengthProblem::ArcLengthProblem(NonlinearProblem& problem,
                                   std::function<void(double)> set_load_factor,
                                   bool prescribed_move)
    : problem_(problem),
      set_load_factor_(std::move(set_load_factor)),
      prescribed_move_(prescribed_move) {}

void ArcLengthProblem::begin_step() {
  problem_.path_weights(weights_);
  converged_lpf_ = delta_lpf_ = previous_lpf_ = 0.0;
  delta_q_.setZero(problem_.size());
  previous_q_.setZero(problem_.size());
  scale_squared_ = 0.0;
  has_previous_ = false;
  attempt_ = Attempt::Secant;
}

void ArcLengthProblem::begin_increment(double arc) {
  arc_ = arc;
  delta_lpf_ = 0.0;
  delta_q_.setZero(problem_.size());
  farthest_.setZero(problem_.size());
  largest_residual_ = -1;
  predicting_ = true;
}

void ArcLengthProblem::hold(int equation) {
  // No farther than the secant predictor takes that equation, nor than the arc length would take
  // it alone.
  held_ = equation;
  held_value_ = 0.0;
  if (held_ < 0) return;
  double reach = std::sqrt(2.0 * scale_squared_ / weights_[held_]) * arc_;
  if (previous_q_[held_] * farthest_[held_] > 0) {
    reach = std::min(reach, std::abs(previous_q_[held_]) * arc_ / previous_length());
  }
  held_value_ = std::clamp(farthest_[held_], -reach, reach);
}

bool ArcLengthProblem::attempt_failed() {
  switch (attempt_) {
    case Attempt::Secant:
      hold(largest_residual_);
      held_retries_ = 0;
      held_switched_ = false;
      attempt_ = Attempt::Reversed;
      return true;
    case Attempt::Reversed:
      attempt_ = held_value_ != 0.0 ? Attempt::Held : Attempt::Secant;
      return attempt_ == Attempt::Held;
    case Attempt::Held:
      // Equilibrium found too far along the path: held again proportionally nearer.
      if (held_distance_ > kHeldReach * arc_ && ++held_retries_ <= 2) {
        held_value_ *= arc_ / held_distance_;
        return true;
      }
      // Another equation out of balance once the held one is in balance (a second connector at
      // its peak): held instead, once.
      if (!held_switched_ && out_of_balance_ >= 0) {
        held_switched_ = true;
        held_retries_ = 0;
        hold(out_of_balance_);
        if (held_value_ != 0.0) return true;
      }
      attempt_ = Attempt::Secant;
      return false;
  }
  return false;
}

void ArcLengthProblem::commit() {
  previous_q_ = delta_q_;
  previous_lpf_ = delta_lpf_;
  converged_lpf_ += delta_lpf_;
  delta_lpf_ = 0.0;
  delta_q_.setZero();
  has_previous_ = true;
  attempt_ = Attempt::Secant;
}

double ArcLengthProblem::scaled_dot(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const {
  return x.cwiseProduct(weights_).dot(y) / scale_squared_;
}

void ArcLengthProblem::track_attempt() {
  if (predicting_) return;
  // The equation to hold is the one out of balance at the predicted point, before the
  // corrections (which may diverge) move the imbalance elsewhere.
  const bool first = largest_residual_ < 0;
  double largest = 0.0, largest_other = 0.0;
  out_of_balance_ = -1;
  for (int i = 0; i < problem_.size(); ++i) {
    if (weights_[i] == 0.0) continue;
    const double ahead = previous_q_[i] != 0.0 ? std::copysign(1.0, previous_q_[i]) : 0.0;
    const bool farther = ahead != 0.0 ? ahead * delta_q_[i] > ahead * farthest_[i]
                                      : std::abs(delta_q_[i]) > std::abs(farthest_[i]);
    if (farther) farthest_[i] = delta_q_[i];
    if (first && std::abs(residual_[i]) > largest) {
      largest = std::abs(residual_[i]);
      largest_residual_ = i;
    }
    if (i != held_ && std::abs(residual_[i]) > largest_other) {
      largest_other = std::abs(residual_[i]);
      out_of_balance_ = i;
    }
  }
}

double ArcLengthProblem::previous_length() const {
  return std::sqrt(0.5 * (scaled_dot(previous_q_, previous_q_) + previous_lpf_ * previous_lpf_));
}

double ArcLengthProblem::constraint() const {
  if (scale_squared_ == 0.0) return 0.0;  // before the first predictor: nothing to measure
  if (holding()) return delta_q_[held_] - held_value_;
  return 0.5 * (scaled_dot(delta_q_, delta_q_) + delta_lpf_ * delta_lpf_) - arc_ * arc_;
}

EvalStatus ArcLengthProblem::evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) {
  // r is linear in λ (the step's values are ramps in λ), so its rate is the difference of two
  // residuals one unit apart at the same state; the second evaluation leaves the conditions at λ.
  set_load_factor_(load_factor() + 1.0);
  if (prescribed_move_ && shifted_tangent_.n == 0) shifted_tangent_ = problem_.pattern();
  EvalStatus status =
      problem_.evaluate(shifted_residual_, prescribed_move_ ? &shifted_tangent_ : nullptr);
  set_load_factor_(load_factor());
  if (!status.ok) return status;
  status = problem_.evaluate(residual_, tangent);
  if (!status.ok) return status;
  load_rate_ = shifted_residual_ - residual_;
  const int n = problem_.size();
  track_attempt();
  residual.resize(n + 1);
  residual.head(n) = residual_;
  residual[n] = constraint();
  return status;
}

void ArcLengthProblem::apply_correction(const Eigen::VectorXd& correction) {
  const int n = problem_.size();
  const Eigen::VectorXd dq = correction.head(n);
  problem_.apply_correction(dq);
  // Ahead, in the first increment of a path, is where its tangent predictor went.
  if (predicting_ && !has_previous_ && attempt_ == Attempt::Secant) previous_q_ = dq;
  delta_q_ += dq;
  delta_lpf_ += correction[n];
  predicting_ = false;
}

void ArcLengthProblem::measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
                               IterationNorms& norms) const {
  const int n = problem_.size();
  const Eigen::VectorXd r = residual.head(n);
  if (correction) {
    const Eigen::VectorXd c = correction->head(n);
    problem_.measure(r, &c, norms);
  } else {
    problem_.measure(r, nullptr, norms);
  }
  // The point may sit off the sphere by 1e-6 of its radius squared: every point that satisfies
  // equilibrium lies on the path, and the constraint only chooses which.
  const double tolerance = holding() ? 1e-6 * std::abs(held_value_) : 1e-6 * arc_ * arc_;
  if (tolerance > 0) {
    norms.constraint_violation =
        std::max(norms.constraint_violation, std::abs(residual[n]) / tolerance);
  }
  // Only a point ahead of the last converged one in the displacements continues the path: one
  // behind it lies on the elastic unloading branch of a softened law (docs/riks.md).
  if (has_previous_ && !holding() && scaled_dot(delta_q_, previous_q_) <= 0) {
    norms.constraint_violation = std::numeric_limits<double>::infinity();
  }
  // A held displacement does not bound the rest of the increment: a point far beyond the arc
  // length on the sphere skips part of the path (a snap-back) and is tried again nearer.
  if (holding()) {
    held_distance_ = std::sqrt(0.5 * (scaled_dot(delta_q_, delta_q_) + delta_lpf_ * delta_lpf_));
    if (held_distance_ > kHeldReach * arc_) {
      norms.constraint_violation = std::numeric_limits<double>::infinity();
    }
  }
  // Nor does a point where the load falls while a damaged model only unloads: past a softening
  // limit point the load falls because damage grows; without growth the whole model is going
  // back along its elastic unloading branch. In the first increment, which has no direction to
  // keep, the load falls only where it is tried reversed, and only growing damage makes that
  // the path (a path that starts at a softening peak).
  if (delta_lpf_ < 0) {
    const DamageChange change = problem_.damage_change();
    if (has_previous_ ? change.damaged && !change.growing : !change.growing) {
      norms.constraint_violation = std::numeric_limits<double>::infinity();
    }
  }
}

bool ArcLengthProblem::correction(const Eigen::VectorXd& rhs, const Eigen::VectorXd& a,
                                  const Eigen::VectorXd& v, Eigen::VectorXd& out) {
  const int n = problem_.size();
  out.resize(n + 1);
  double dlpf = 0.0;
  if (holding()) {
    // The held equation at its value, the predictor and the corrections alike (the constraint is
    // linear): λ from the linear response.
    if (!(std::abs(v[held_]) > 0)) return false;
    dlpf = (rhs[n] - a[held_]) / v[held_];
  } else if (predicting_) {
    // ū: the weighted size of the response to a unit λ at the step's first predictor.
    if (scale_squared_ == 0.0) {
      const double size = v.cwiseProduct(weights_).dot(v);
      scale_squared_ = size > 0 ? size : 1.0;
    }
    // The root that continues the path. Later increments go on in the direction of the last
    // converged one (a secant predictor): at a damaged state the tangent cannot tell loading
    // from unloading, and the elastic unloading branch is an equilibrium path too. The first
    // increment of a step goes along the tangent (v, 1), with λ growing. Either is scaled to
    // the length Δl.
    if (has_previous_) {
      const double previous = previous_length();
      if (previous > 0) {
        const double scale = arc_ / previous;
        out.head(n) = a + scale * previous_q_;
        out[n] = scale * previous_lpf_;
        if (reversing()) out[n] = -out[n];
        return true;
      }
    }
    dlpf = arc_ / std::sqrt(0.5 * (scaled_dot(v, v) + 1.0));
    if (reversing()) dlpf = -dlpf;
  } else {
    // The linearised constraint: ∂g/∂q = W Δq / ū², ∂g/∂λ = Δλ.
    const double along = scaled_dot(delta_q_, v) + delta_lpf_;
    const double scale = std::abs(scaled_dot(delta_q_, delta_q_)) + delta_lpf_ * delta_lpf_;
    if (!(std::abs(along) > 1e-12 * std::sqrt(scale) * std::sqrt(0.5 * (scaled_dot(v, v) + 1)))) {
      return false;
    }
    dlpf = (rhs[n] - scaled_dot(delta_q_, a)) / along;
  }
  out.head(n) = a + dlpf * v;
  out[n] = dlpf;
  return true;
}

}  // namespace clinch
