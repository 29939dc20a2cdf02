// Elements with dependent DOFs (docs/constraints.md "Elimination"): an element evaluates over its
// own DOFs as always; its local system is then condensed onto the independent DOFs, r' = Tᵀr and
// K' = TᵀKT, where the rows of T are the gradients of its dependent DOFs (dependent_motion.hpp).
// The forces it puts on dependent DOFs are kept in those rows of the internal force vector: the
// NLGEOM curvature of the maps and the reactions read them.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "src/assembly/analysis_plan.hpp"
#include "src/assembly/connector_element.hpp"
#include "src/assembly/dependent_motion.hpp"

namespace clinch {

// Records an expansion for every connector and spring that has a dependent DOF.
void expand_constrained_elements(AnalysisPlan& plan);

// The equations an element's condensed entries go to (those of an element without expansion).
std::span<const int> scatter_equations(const AnalysisPlan& plan, const LocalEquations& local,
                                       std::int32_t expansion);

struct CondensedLocal {
  Eigen::VectorXd r;
  Eigen::MatrixXd k;
  Eigen::MatrixXd kt;  // K T, the first half of the product
  struct Entry {
    int row = 0, place = 0;
    double coefficient = 0;
  };
  std::vector<Entry> transform;  // the non-zeros of T
};

// Condenses `local` (over the element's equations `l`) onto expansion `e`; adds the forces on the
// dependent rows to `internal`.
void condense(const ElementExpansion& e, const LocalEquations& l, const DependentDofs& dofs,
              const DependentMotion& motion, const LocalSystem& local, bool want_tangent,
              CondensedLocal& out, Eigen::VectorXd& internal);

}  // namespace clinch
