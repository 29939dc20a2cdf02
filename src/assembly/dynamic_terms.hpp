// What a dynamic increment adds to the equations of motion (docs/dynamics.md): the Newmark
// relations that give the velocity and acceleration of every nodal equation from its value, and
// the inertia of the lumped nodal masses (nodal_inertia.hpp) in the Hilber–Hughes–Taylor α form
//   M a₁ + (1 + α)(I(u₁, v₁) − P₁) − α (I₀ − P₀) = 0,
// divided by (1 + α) so that the element and constraint rows keep their static form:
//   (I − P) + (M a₁ − α r₀)/(1 + α) = 0,  r₀ = I₀ − P₀ at the start of the increment.
// Backward Euler (APPLICATION=QUASI-STATIC) has α = 0, v₁ = (u₁ − u₀)/Δt, a₁ = (v₁ − v₀)/Δt.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "src/assembly/analysis_state.hpp"
#include "src/assembly/dependent_dofs.hpp"
#include "src/assembly/increment_conditions.hpp"
#include "src/assembly/nodal_inertia.hpp"
#include "src/model/history_model.hpp"

namespace clinch {

// The integration operator over one increment of length dt.
struct NewmarkIncrement {
  double dt = 0, alpha = 0, beta = 0.25, gamma = 0.5;
  bool backward_euler = false;
  double da_du = 0, dv_du = 0;  // ∂a₁/∂u₁ and ∂v₁/∂u₁ (the same for every equation)

  static NewmarkIncrement of(const DynamicProcedure& procedure, double dt);
  // v₁ and a₁ of every nodal equation at the trial values, from the converged state.
  void update_rates(AnalysisState& state) const;
  // u₁ whose velocity (order 1) or acceleration (order 2) is `rate`, from u₀, v₀, a₀: the same
  // relations solved the other way (a prescribed rate, *BOUNDARY TYPE=VELOCITY/ACCELERATION).
  double value_of_rate(double u0, double v0, double a0, int order, double rate) const;
  // The state halfway through the increment, from the converged state and the solved end of the
  // increment (the half-increment residual, docs/dynamics.md "Automatic incrementation"): the
  // acceleration is the mean of the start and end ones, and the values and velocities are
  // Newmark's relations over Δt/2 with it; backward Euler, and the multipliers, take the means of
  // the start and end values.
  void set_half_increment_state(AnalysisState& state, const DofMap& dofs) const;
};

// Where the inertia terms go: the residual over every equation, the tangent in the storage of
// `pattern` (null: residual only), and the predictor of prescribed values (ConnectorSystem).
struct InertiaTarget {
  Eigen::VectorXd& residual;
  SparseMatrix* tangent;
  const std::vector<int>& diagonal;  // position of each solved equation's diagonal entry
  bool symmetric;
  Eigen::VectorXd* predictor;       // non-null while prescribed values are short of their targets
  const DependentDofs& dependents;  // the tangent is over the solved equations
};

// Adds (M a₁ − α r₀)/(1 + α) to the rows of free nodal equations and ∂/∂u₁ of it to the tangent
// (a block with a dependent DOF is left to add_constrained_inertia, constrained_inertia.hpp);
// `inertia_force` gets M a₁ per equation (a reaction includes it) and `entries` its magnitudes
// (the force flux q̃ of the convergence criteria).
void add_inertia(std::span<const NodeInertia> inertia, const NewmarkIncrement& increment,
                 const AnalysisState& state, const IncrementConditions& conditions,
                 InertiaTarget target, Eigen::VectorXd& inertia_force, ForceEntries& entries);

// a = M⁻¹(−r) on the DOFs that carry inertia and are free (INITIAL=YES: the accelerations at the
// start of a step from its equilibrium); 0 elsewhere.
void initial_accelerations(std::span<const NodeInertia> inertia,
                           const IncrementConditions& conditions, const Eigen::VectorXd& r,
                           Eigen::VectorXd& a);

// ½ vᵀ M v of the nodal masses (ALLKE); under NLGEOM (`rotations` of the nodes, not empty) the
// rotary inertia's ½ W·JW in the body's axes (rotary_inertia_finite.hpp).
double kinetic_energy(std::span<const NodeInertia> inertia, const Eigen::VectorXd& v,
                      const std::vector<Matrix3>& rotations);

}  // namespace clinch
