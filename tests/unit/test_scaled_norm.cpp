// ScaledNorm (base/scaled_norm.hpp) against norms worked by hand where a plain sum of squares
// overflows or underflows.
#include "base/scaled_norm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace clinch {
namespace {

double norm_of(std::initializer_list<double> values) {
  ScaledNorm norm;
  for (double v : values) norm.add(v);
  return norm.value();
}

TEST(ScaledNorm, OrdinaryValues) {
  EXPECT_DOUBLE_EQ(norm_of({}), 0.0);
  EXPECT_DOUBLE_EQ(norm_of({0.0, -0.0}), 0.0);
  // 3-4-5, in either order and with zeros between.
  EXPECT_DOUBLE_EQ(norm_of({3.0, 0.0, -4.0}), 5.0);
  EXPECT_DOUBLE_EQ(norm_of({-4.0, 3.0}), 5.0);
}

// 3e200 and 4e200: the squares (9e400) overflow; the norm is 5e200 (to a few ulps: two
// rescalings, each a relative error of about 1e-16).
TEST(ScaledNorm, EntriesWhoseSquaresOverflow) {
  EXPECT_NEAR(norm_of({3e200, 4e200}), 5e200, 5e200 * 1e-15);
  // √2·1e308 is inside the double range (up to 1.797e308); √2·1.5e308 is not and overflows.
  EXPECT_NEAR(norm_of({1e308, 1e308}), std::sqrt(2.0) * 1e308, 1e308 * 1e-15);
  EXPECT_EQ(norm_of({1.5e308, 1.5e308}), std::numeric_limits<double>::infinity());
  EXPECT_NEAR(norm_of({1e308, 1e307}), 1e308 * std::sqrt(1.01), 1e308 * 1e-15);
}

// 3e-200 and 4e-200: the squares underflow to 0; the norm is 5e-200.
TEST(ScaledNorm, EntriesWhoseSquaresUnderflow) {
  EXPECT_NEAR(norm_of({3e-200, 4e-200}), 5e-200, 5e-200 * 1e-15);
  EXPECT_DOUBLE_EQ(norm_of({1.0, 1e-200}), 1.0);
}

TEST(ScaledNorm, NonFiniteValuesAreNotHidden) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(norm_of({1.0, -inf, 2.0}), inf);
  EXPECT_EQ(norm_of({inf, inf}), inf);
  EXPECT_TRUE(std::isnan(norm_of({1.0, std::nan(""), inf})));
}

}  // namespace
}  // namespace clinch
