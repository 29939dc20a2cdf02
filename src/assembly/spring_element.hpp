// SPRINGA, SPRING1 and SPRING2 elements (keywords.md §7), and the DASHPOTA, DASHPOT1 and
// DASHPOT2 elements that share their kinematics (behaviors.md §8): Δ from the nodal values, the
// law of Δ (a dashpot: of Δ's rate), and the local residual and tangent on the element's columns.
#pragma once

#include "src/assembly/connector_element.hpp"

namespace clinch {

// What an evaluation computed for one spring or dashpot (S11 and E11).
struct SpringResult {
  double force = 0, delta = 0;
};

// The nodal values an evaluation reads: the trial ones, and for a dashpot's velocity the last
// converged ones and the time increment, or in a dynamic step the nodal velocities with their
// derivative by the nodal values (dynamic_terms.hpp).
struct SpringMotion {
  const Eigen::VectorXd& x;
  const Eigen::VectorXd& x_n;
  double dt = 0;
  bool nlgeom = false;
  const Eigen::VectorXd* velocity = nullptr;  // non-null in a dynamic step
  double dv_du = 0;
};

void evaluate_spring(const AnalysisPlan& plan, const SpringRecord& s, const SpringMotion& motion,
                     bool want_tangent, LocalSystem& local, SpringResult& result);

}  // namespace clinch
