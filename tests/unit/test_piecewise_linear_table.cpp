// PiecewiseLinearTable (behaviors.md §1.2, §4.2): interpolation, the right-hand slope at
// breakpoints, CONSTANT and LINEAR extrapolation, one-row tables and the outside flag. Values are
// checked against hand-computed ones on the table of the §4.5 E2 example.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "src/behavior/piecewise_linear_table.hpp"

namespace clinch {
namespace {

// §4.5 E2: force at motion (-0.1, -100), (0, 0), (0.1, 100), (0.2, 150); slopes 1000, 1000, 500.
PiecewiseLinearTable e2_table(Extrapolation extrapolation) {
  return PiecewiseLinearTable({-0.1, 0.0, 0.1, 0.2}, {-100.0, 0.0, 100.0, 150.0}, extrapolation);
}

// Interpolated values involve one multiplication and a few additions of O(100) numbers, so a
// relative rounding error of a few ulps: 1e-12 absolute is ample and still far below any
// plausible mistake (the smallest wrong answer, a wrong segment, is off by O(1)).
constexpr double kTol = 1e-12;

TEST(PiecewiseLinearTable, InterpolatesInsideSegments) {
  const auto table = e2_table(Extrapolation::Constant);
  const TableSample a = table.evaluate(-0.05);
  EXPECT_NEAR(a.value, -50.0, kTol);
  EXPECT_DOUBLE_EQ(a.slope, 1000.0);
  EXPECT_FALSE(a.outside);
  const TableSample b = table.evaluate(0.15);
  EXPECT_NEAR(b.value, 125.0, kTol);
  EXPECT_DOUBLE_EQ(b.slope, 500.0);
  EXPECT_FALSE(b.outside);
}

TEST(PiecewiseLinearTable, BreakpointTakesTheRightHandSlope) {
  const auto table = e2_table(Extrapolation::Constant);
  const TableSample s = table.evaluate(0.1);  // between slopes 1000 (left) and 500 (right)
  EXPECT_DOUBLE_EQ(s.value, 100.0);
  EXPECT_DOUBLE_EQ(s.slope, 500.0);
  EXPECT_FALSE(s.outside);
  const TableSample first = table.evaluate(-0.1);
  EXPECT_DOUBLE_EQ(first.value, -100.0);
  EXPECT_DOUBLE_EQ(first.slope, 1000.0);
  EXPECT_FALSE(first.outside);
}

TEST(PiecewiseLinearTable, LastPointIsInsideWithTheExtrapolatedSlope) {
  const TableSample c = e2_table(Extrapolation::Constant).evaluate(0.2);
  EXPECT_DOUBLE_EQ(c.value, 150.0);
  EXPECT_DOUBLE_EQ(c.slope, 0.0);
  EXPECT_FALSE(c.outside);
  const TableSample l = e2_table(Extrapolation::Linear).evaluate(0.2);
  EXPECT_DOUBLE_EQ(l.value, 150.0);
  EXPECT_DOUBLE_EQ(l.slope, 500.0);
  EXPECT_FALSE(l.outside);
}

TEST(PiecewiseLinearTable, ConstantExtrapolationHoldsEndValuesWithZeroSlope) {
  const auto table = e2_table(Extrapolation::Constant);
  const TableSample below = table.evaluate(-0.3);
  EXPECT_DOUBLE_EQ(below.value, -100.0);
  EXPECT_DOUBLE_EQ(below.slope, 0.0);
  EXPECT_TRUE(below.outside);
  const TableSample above = table.evaluate(0.3);
  EXPECT_DOUBLE_EQ(above.value, 150.0);
  EXPECT_DOUBLE_EQ(above.slope, 0.0);
  EXPECT_TRUE(above.outside);
}

TEST(PiecewiseLinearTable, LinearExtrapolationContinuesEndSegments) {
  const auto table = e2_table(Extrapolation::Linear);
  const TableSample below = table.evaluate(-0.3);  // -100 + 1000·(-0.2)
  EXPECT_NEAR(below.value, -300.0, kTol);
  EXPECT_DOUBLE_EQ(below.slope, 1000.0);
  EXPECT_TRUE(below.outside);
  const TableSample above = table.evaluate(0.3);  // 150 + 500·0.1 (E2, t = 1: 200)
  EXPECT_NEAR(above.value, 200.0, kTol);
  EXPECT_DOUBLE_EQ(above.slope, 500.0);
  EXPECT_TRUE(above.outside);
}

TEST(PiecewiseLinearTable, OneRowIsAConstant) {
  for (Extrapolation e : {Extrapolation::Constant, Extrapolation::Linear}) {
    const PiecewiseLinearTable table({2.0}, {7.0}, e);
    for (double x : {-5.0, 2.0, 9.0}) {
      const TableSample s = table.evaluate(x);
      EXPECT_EQ(s.value, 7.0);
      EXPECT_EQ(s.slope, 0.0);
      EXPECT_EQ(s.outside, x != 2.0);
    }
  }
}

TEST(PiecewiseLinearTable, FromPointsReadsValueAtAbscissa) {
  std::vector<TablePoint> points(2);
  points[0].value = 1.0;
  points[0].at = 10.0;
  points[1].value = 3.0;
  points[1].at = 20.0;
  const auto table = PiecewiseLinearTable::from_points(points, Extrapolation::Constant);
  EXPECT_EQ(table.size(), 2u);
  const TableSample s = table.evaluate(15.0);
  EXPECT_NEAR(s.value, 2.0, kTol);
  EXPECT_DOUBLE_EQ(s.slope, 0.2);
}

TEST(PiecewiseLinearTable, NanPropagates) {
  const TableSample s =
      e2_table(Extrapolation::Constant).evaluate(std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(s.value));
  EXPECT_TRUE(std::isnan(s.slope));
}

TEST(PiecewiseLinearTable, RejectsTablesValidationWouldHaveRejected) {
  EXPECT_THROW(PiecewiseLinearTable({}, {}, Extrapolation::Constant), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinearTable({0.0, 1.0}, {0.0}, Extrapolation::Constant),
               std::invalid_argument);
  EXPECT_THROW(PiecewiseLinearTable({0.0, 1.0, 1.0}, {0.0, 1.0, 2.0}, Extrapolation::Constant),
               std::invalid_argument);
}

}  // namespace
}  // namespace clinch
