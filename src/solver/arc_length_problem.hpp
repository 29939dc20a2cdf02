// The system Newton solves in an increment of a Riks step (docs/riks.md): the problem's
// equilibrium residual r(q, λ) at the load proportionality factor λ (the step's values at
// P₀ + λ(P_ref − P₀)), bordered by the arc-length constraint of the increment
//   g(Δq, Δλ) = ½(‖Δq‖²_w / ū² + Δλ²) − Δl² = 0,
// a sphere of radius Δl in the scaled load-displacement space: Δq and Δλ are the changes since
// the converged state, w the problem's path weights (translations, rotations times L̄, no
// multipliers) and ū the weighted size of the response to a unit λ at the start of the step, so
// that a linear response covers Δλ = Δl (the manual's Δλ_in = Δl_in / l_period).
//
// The unknowns are (q, λ): size() is one more than the problem's, and the last entry of residuals
// and corrections is g and δλ. The tangent Newton assembles is the problem's K; the border
// (∂r/∂λ, ∂g/∂q, ∂g/∂λ) stays here and BorderedSolver (bordered_solver.hpp) eliminates it:
//   δq = a + δλ v,  K a = −r,  K v = −∂r/∂λ,  δλ = (−g − ∂g/∂q·a) / (∂g/∂q·v + ∂g/∂λ).
// The first correction of an increment is the predictor along the tangent v (Newton does not
// test the state before it); the corrections after it solve the consistently linearised
// constraint.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "src/solver/nonlinear_problem.hpp"
#include "src/solver/step_problem.hpp"

namespace clinch {

class ArcLengthProblem final : public NonlinearProblem {
 public:
  // λ scales the step's values (a Riks step: StepProblem::set_load_factor) ...
  ArcLengthProblem(NonlinearProblem& problem, StepProblem& step);
  // ... or whatever `set_load_factor` applies at λ (increment_path.hpp: the step's values
  // ramped inside an increment, prescribed ones too); r must be linear in λ for ∂r/∂λ to be
  // exact. Where prescribed values move with λ, their columns reach the other equations through
  // the problem's predictor (K_fp (target − u_p), which it adds when it assembles a tangent), so
  // ∂r/∂λ is then taken between two residuals evaluated with tangents.
  ArcLengthProblem(NonlinearProblem& problem, std::function<void(double)> set_load_factor,
                   bool prescribed_move = false);

  // ---- the step and its increments ----
  // Starts the step at λ = 0 (the step's values at P₀).
  void begin_step();
  // Starts an increment of arc length `arc` from the converged state.
  void begin_increment(double arc);
  // The converged increment becomes the start of the next one.
  void commit();
  // An attempt from the converged state failed (before the next one is begun); true when the
  // same arc length is to be tried again. Each arc length from a converged state is tried up to
  // three ways before it is cut back (docs/riks.md "At a kink"): the secant predictor on the
  // sphere, then the same with Δλ reversed, then with one displacement held ahead (in the first
  // increment, which has no direction to keep: the tangent predictor, then the same with λ
  // falling).
  bool attempt_failed();
  // Reversed: the last increment's Δq with its Δλ reversed. Past a limit point on a kink of a
  // law (damage starting at its peak with a steep softening) the path goes on in the
  // displacements with the load falling, and the secant predictor, which keeps the load rising,
  // finds no equilibrium.
  bool reversing() const { return attempt_ == Attempt::Reversed; }
  // Held: the equation whose residual was largest at the secant attempt's predicted point (the
  // one whose law passed its peak) is held where that attempt took it farthest ahead, and λ
  // follows from equilibrium. Under one λ, the connectors that unload while another passes its
  // peak can outweigh it on the sphere, which then cuts the path only behind the last point.
  // Where that fails with another equation out of balance (a second connector at its peak), that
  // one is held instead, once.
  bool holding() const { return attempt_ == Attempt::Held; }
  double load_factor() const { return converged_lpf_ + delta_lpf_; }
  // Before the increment's first correction: the next one is the predictor.
  bool predicting() const { return predicting_; }

  // ---- NonlinearProblem ----
  int size() const override { return problem_.size() + 1; }
  const SparseMatrix& pattern() const override { return problem_.pattern(); }
  EvalStatus evaluate(Eigen::VectorXd& residual, SparseMatrix* tangent) override;
  void apply_correction(const Eigen::VectorXd& correction) override;
  bool moving_prescribed() const override { return predicting_; }
  void measure(const Eigen::VectorXd& residual, const Eigen::VectorXd* correction,
               IterationNorms& norms) const override;

  // ---- the border, for BorderedSolver ----
  // ∂r/∂λ at the last evaluation (exact: r is linear in λ).
  const Eigen::VectorXd& load_rate() const { return load_rate_; }
  // The border's last row ∂g/∂(q, λ): W Δq / ū² in the problem's columns, Δλ in the last
  // (the sphere); 1 in the held equation's column, 0 elsewhere (a held displacement).
  double constraint_gradient(int column) const {
    if (holding()) return column == held_ ? 1.0 : 0.0;
    return column < problem_.size() ? weights_[column] * delta_q_[column] / scale_squared_
                                    : delta_lpf_;
  }
  // The correction (δq, δλ) from the solutions a = K⁻¹(head of `rhs`) and v = −K⁻¹ ∂r/∂λ; false
  // when the bordered system is singular (the constraint does not cut the tangent).
  // The predictor also fixes ū at the step's first increment.
  bool correction(const Eigen::VectorXd& rhs, const Eigen::VectorXd& a, const Eigen::VectorXd& v,
                  Eigen::VectorXd& out);

 private:
  double scaled_dot(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const;
  double constraint() const;
  double previous_length() const;  // the last converged increment's length on the sphere
  void track_attempt();            // farthest_ and largest_residual_ after an evaluation
  void hold(int equation);         // held_ and held_value_ for the next held attempt

  NonlinearProblem& problem_;
  std::function<void(double)> set_load_factor_;
  bool prescribed_move_ = false;
  SparseMatrix shifted_tangent_;  // scratch for ∂r/∂λ when prescribed values move
  Eigen::VectorXd weights_;
  Eigen::VectorXd residual_, shifted_residual_, load_rate_;
  Eigen::VectorXd delta_q_, previous_q_;  // this increment's Δq; the last converged one's
  double converged_lpf_ = 0.0, delta_lpf_ = 0.0, previous_lpf_ = 0.0;
  double arc_ = 0.0;
  double scale_squared_ = 0.0;  // ū², 0 until the first predictor sets it
  bool predicting_ = false;
  bool has_previous_ = false;
  enum class Attempt { Secant, Reversed, Held };
  Attempt attempt_ = Attempt::Secant;
  // For the held attempt: per equation, the Δq of this attempt's iterates farthest ahead (along
  // the last increment's Δq, or the first increment's predictor); the equation of the largest
  // residual at the attempt's predicted point; the equation held and its Δq.
  Eigen::VectorXd farthest_;
  int largest_residual_ = -1;
  int out_of_balance_ = -1;  // the largest residual but the held one's, at the last evaluation
  int held_ = -1;
  double held_value_ = 0.0;
  // A held point counts up to this many arc lengths from the converged one on the sphere.
  static constexpr double kHeldReach = 2.0;
  mutable double held_distance_ = 0.0;  // of the last evaluation of a held attempt
  int held_retries_ = 0;
  bool held_switched_ = false;  // the held equation was changed once from this arc length
};

}  // namespace clinch
