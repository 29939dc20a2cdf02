// The motion of the dependent DOFs at the current state (dependent_dofs.hpp): their values from
// the independent ones, the gradient of each map over the independent equations (what moves an
// element's entries on a dependent DOF to the DOFs it depends on), and, under NLGEOM, the second
// derivatives of the curved maps (rigid arms and links) that a force on the DOF turns into
// stiffness (docs/constraints.md "Elimination").
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "src/assembly/dependent_dofs.hpp"

namespace clinch {

struct CurvatureEntry {
  int row = -1, column = -1;
  double value = 0;
};

class DependentMotion {
 public:
  DependentMotion(const DependentDofs& dofs, const DofMap& map);

  // Sets every dependent DOF from the independent ones, and under NLGEOM the rotation of each
  // node that follows another's. False with `why` when a link can no longer keep its length.
  bool update_values(Eigen::VectorXd& x, std::vector<Matrix3>& rotation, bool nlgeom,
                     std::string* why) const;
  // The gradients at the current state (NLGEOM: the rotated arms, the link's direction).
  void update_gradients(const Eigen::VectorXd& x, const std::vector<Matrix3>& rotation,
                        bool nlgeom);
  // ∂u_d/∂q over DependentDofs::resolved_equation of `d` (after update_gradients).
  std::span<const double> gradient(const DependentDof& d) const {
    return {resolved_.data() + d.first_resolved, d.resolved_count};
  }
  // f·∂²u_d/∂q∂q of a curved map under NLGEOM, over its first-level equations (spins of the
  // reference node for a rigid arm), appended to `out`.
  void add_curvature(const DependentDof& d, double f, const Eigen::VectorXd& x,
                     const std::vector<Matrix3>& rotation, std::vector<CurvatureEntry>& out) const;

 private:
  // The arm of a rigid translation in the current configuration.
  Vector3 current_arm(const DependentDof& d, const std::vector<Matrix3>& rotation,
                      bool nlgeom) const;
  // A link's current d_j = x_j − x_other,j (j ≠ axis) and its signed h = x_k − x_other,k.
  bool link_state(const DependentDof& d, const Eigen::VectorXd& x, Vector3& gap, double& h) const;
  double value_at(const Eigen::VectorXd& x, std::uint32_t term) const {
    const int eq = dofs_.term_equation[term];
    return eq >= 0 ? x[eq] : 0.0;
  }

  const DependentDofs& dofs_;
  const DofMap& map_;
  std::vector<double> first_;     // first-level coefficients
  std::vector<double> resolved_;  // substituted gradients
};

}  // namespace clinch
