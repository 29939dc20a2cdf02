// Inertia on DOFs that a kinematic constraint eliminates (docs/dynamics.md "Inertia on
// constrained nodes"): a MASS or ROTARYI on a tie or pin node of a rigid body, on a coupling node,
// on a node of an *EQUATION or MPC. Such a node's block (its three translations, or its three
// rotations) is condensed like a constrained element (constrained_elements.hpp): with T the rows
// of the block's DOFs over the independent equations (a unit row for an independent DOF, the
// gradient of the map for a dependent one), the inertia force f = M a at the block's DOFs goes to
// the independent rows as Tᵀf and its tangent is Tᵀ (∂a/∂u M) T. A dependent DOF's displacement
// follows from the constraint, its velocity and acceleration from its own displacement history
// by the step's operator (NewmarkIncrement::update_rates), as an independent DOF's do; under
// NLGEOM the force on it also enters the curvature of the map (ConnectorSystem).
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "src/assembly/dependent_motion.hpp"
#include "src/assembly/dynamic_terms.hpp"
#include "src/assembly/increment_conditions.hpp"
#include "src/assembly/nodal_inertia.hpp"

namespace clinch {

// One node's block mapped onto the independent equations it moves with.
struct MappedInertiaBlock {
  std::array<int, 3> eq{-1, -1, -1};  // the block's DOFs (−1: not active)
  Matrix3 m = Matrix3::Zero();
  int field = 0;                               // 0: translations (forces), 1: rotations (moments)
  std::vector<int> columns;                    // independent equations, each once
  Eigen::Matrix<double, 3, Eigen::Dynamic> t;  // ∂u_block/∂u_columns
};

// Whether a block has a dependent DOF (then it is assembled here, not in add_inertia).
bool has_dependent_dof(const std::array<int, 3>& eq, const DependentDofs& dofs);

// The blocks of `inertia` with a dependent DOF, mapped at the current gradients of `motion`.
std::vector<MappedInertiaBlock> mapped_inertia_blocks(std::span<const NodeInertia> inertia,
                                                      const DependentDofs& dofs,
                                                      const DependentMotion& motion);

// The independent equations each constrained block couples (the assembly pattern), with the
// gradients' structure only: the values of T are not needed.
std::vector<std::vector<int>> constrained_inertia_couplings(std::span<const NodeInertia> inertia,
                                                            const DependentDofs& dofs);

// Adds (Tᵀ M a)/(1 + α) of every constrained block to the free independent rows and its tangent
// (solved numbering, through `target`); `inertia_force` gets M a at the block's dependent DOFs
// and Tᵀ M a added at the independent ones (a prescribed one's reaction includes it).
void add_constrained_inertia(const std::vector<MappedInertiaBlock>& blocks,
                             const NewmarkIncrement& increment, const AnalysisState& state,
                             const IncrementConditions& conditions, InertiaTarget target,
                             Eigen::VectorXd& inertia_force, ForceEntries& entries);

// (M a) at the dependent DOFs of `blocks` (the others untouched).
void dependent_inertia_forces(const std::vector<MappedInertiaBlock>& blocks,
                              const DependentDofs& dofs, const Eigen::VectorXd& a,
                              Eigen::VectorXd& out);

// The rates of the dependent DOFs from those of the independent ones at the current state:
// v_d = T v, and with `a` also a_d = T a + vᵀ(∂²u_d/∂q²)v (the velocity-product term of a curved
// map under NLGEOM: ω × (ω × arm) of a rigid arm).
void follow_constraint_rates(const DependentDofs& dofs, const DependentMotion& motion,
                             const Eigen::VectorXd& x, const std::vector<Matrix3>& rotation,
                             bool nlgeom, Eigen::VectorXd& v, Eigen::VectorXd* a);

// INITIAL=YES with constrained inertia: the accelerations of the independent equations the
// constrained blocks move with, from the condensed M̄ a = −r − Σ TᵀM c (c the velocity-product
// terms already in `a` at the dependent DOFs), together with the free blocks that share an
// equation with them; the other blocks keep what initial_accelerations gave them.
void constrained_initial_accelerations(std::span<const NodeInertia> inertia,
                                       const std::vector<MappedInertiaBlock>& blocks,
                                       const IncrementConditions& conditions,
                                       const Eigen::VectorXd& r, Eigen::VectorXd& a);

}  // namespace clinch
