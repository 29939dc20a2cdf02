// Lengths of user coordinates at any finite scale: the squares of coordinates near 1e160 overflow
// and those near 1e-160 underflow, so lengths are computed with scaling. The coincidence
// tolerance of connection-types.md §2.2 then follows the model at any scale, and the orientation
// triad of keywords.md §6 from points near 1e160 is the one from the same points scaled to 1.
#include <gtest/gtest.h>

#include <vector>

#include "src/model/geometry.hpp"
#include "src/model/orientation_triad.hpp"

namespace clinch {
namespace {

TEST(CoordinateScale, LengthOfIsExactWhereTheSquaresOverflowOrUnderflow) {
  EXPECT_DOUBLE_EQ(length_of({3e200, 4e200, 0}), 5e200);
  EXPECT_DOUBLE_EQ(length_of({0, -3e-200, 4e-200}), 5e-200);
  EXPECT_EQ(length_of({0, 0, 0}), 0);
}

Node node_at(const Vec3& x) {
  Node n;
  n.x = x;
  return n;
}

TEST(CoordinateScale, ToleranceFollowsTheBoundingBoxAtAnyScale) {
  // tol = 1e-8 × max(1, diagonal): the diagonal of a box 3e160 × 4e160 is 5e160.
  const std::vector<Node> far = {node_at({1e160, 0, 0}), node_at({4e160, 4e160, 0})};
  EXPECT_DOUBLE_EQ(geometry_tolerance(far), 5e152);
  const std::vector<Node> tiny = {node_at({1e-160, 0, 0}), node_at({4e-160, 4e-160, 0})};
  EXPECT_EQ(geometry_tolerance(tiny), 1e-8);
  // A diagonal that overflows even with scaling counts as 1, in check and run alike.
  const std::vector<Node> huge = {node_at({-1e308, 0, 0}), node_at({1e308, 0, 0})};
  EXPECT_EQ(geometry_tolerance(huge), 1e-8);
}

TEST(CoordinateScale, OrientationTriadIsTheSameAtAnyScale) {
  Triad unit, far;
  ASSERT_EQ(orientation_triad({1, 1, 0}, {0, 1, 1}, {0, 0, 0}, 1, 0, unit), TriadStatus::Ok);
  ASSERT_EQ(orientation_triad({1e160, 1e160, 0}, {0, 1e160, 1e160}, {0, 0, 0}, 1, 0, far),
            TriadStatus::Ok);
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(far[k][i], unit[k][i], 1e-15) << "axis " << k + 1;
    }
  }
}

}  // namespace
}  // namespace clinch
