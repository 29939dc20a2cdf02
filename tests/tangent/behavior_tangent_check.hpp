// The finite-difference tangent check of behaviors.md §1.4 for a connector behaviour at motion u,
// shared by the elastic and plastic behaviour tests.
#pragma once

#include <gtest/gtest.h>

#include "base/jacobian_check.hpp"
#include "base/small_types.hpp"
#include "src/model/section_model.hpp"

namespace clinch {

// D_fd[:, j] = (f(u + h e_j) − f(u − h e_j))/(2h) with h = 1e-6·max(|u|_∞, u_s), for the
// components in `columns` (the others have no finite difference and are not compared); `force`
// evaluates f from the committed state every time. Passes when
// max|D − D_fd| ≤ 1e-5·max|D| + 1e-8·k_s.
inline void expect_fd_tangent_rule(const VectorFunction& force, const Vector6& u,
                                   const Matrix6& tangent, double u_s, double k_s,
                                   ComponentMask columns = 0b111111) {
  const double h = tangent_check_step(u.cwiseAbs().maxCoeff(), u_s);
  Vector6 steps = Vector6::Zero();
  for (int j = 0; j < 6; ++j) {
    if (has_component(columns, j + 1)) steps[j] = h;
  }
  const JacobianReport report = check_jacobian(perturb_additively(force, u), steps, tangent);
  EXPECT_TRUE(report.meets_tangent_rule(k_s)) << "u = " << u.transpose() << "\n" << report;
}

}  // namespace clinch
