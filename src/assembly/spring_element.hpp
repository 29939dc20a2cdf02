// SPRINGA, SPRING1 and SPRING2 elements (keywords.md §7): the spring's elongation from the nodal
// values, its law, and the local residual and tangent on the spring's columns.
#pragma once

#include "src/assembly/connector_element.hpp"

namespace clinch {

// What an evaluation computed for one spring (S11 and E11).
struct SpringResult {
  double force = 0, delta = 0;
};

void evaluate_spring(const AnalysisPlan& plan, const SpringRecord& s, const Eigen::VectorXd& x,
                     bool nlgeom, bool want_tangent, LocalSystem& local, SpringResult& result);

}  // namespace clinch
