// Hardening laws of connector plasticity (behaviors.md §6.1): tabular isotropic hardening with
// CONSTANT and LINEAR extrapolation (softening included), the exponential law, the yield size
// rule, and the backward-Euler back force of kinematic hardening. Closed forms throughout; the
// only round-off is that of a few floating-point operations (tolerance 1e-12).
#include <gtest/gtest.h>

#include <cmath>

#include "src/behavior/plastic/isotropic_hardening.hpp"
#include "src/behavior/plastic/kinematic_hardening.hpp"

namespace clinch {
namespace {

TablePoint point(double value, double at) {
  TablePoint p;
  p.value = value;
  p.at = at;
  return p;
}

ConnectorPlasticity tabular(Extrapolation e) {
  ConnectorPlasticity p;
  p.component = 1;
  IsotropicHardening iso;
  iso.extrapolation = e;
  iso.table = {point(120, 0), point(170, 0.1), point(150, 0.2)};
  p.isotropic = iso;
  return p;
}

TEST(HardeningIsotropic, TabularInsideAndAtBreakpoints) {
  const auto law = IsotropicHardeningLaw::from_plasticity(tabular(Extrapolation::Constant));
  EXPECT_NEAR(law.at(0.05).value, 145, 1e-12);
  EXPECT_NEAR(law.at(0.05).slope, 500, 1e-12);
  // At a breakpoint: the segment on the right (the one Newton steps onto, §6.3).
  EXPECT_NEAR(law.at(0.1).value, 170, 1e-12);
  EXPECT_NEAR(law.at(0.1).slope, -200, 1e-12);
  EXPECT_NEAR(law.initial(), 120, 1e-12);
}

TEST(HardeningIsotropic, ConstantAndLinearExtrapolation) {
  const auto flat = IsotropicHardeningLaw::from_plasticity(tabular(Extrapolation::Constant));
  EXPECT_NEAR(flat.at(0.5).value, 150, 1e-12);  // perfect plasticity beyond the table
  EXPECT_EQ(flat.at(0.5).slope, 0.0);
  EXPECT_EQ(flat.at(0.2).slope, 0.0);  // the last point's right-hand segment is the flat one
  const auto linear = IsotropicHardeningLaw::from_plasticity(tabular(Extrapolation::Linear));
  EXPECT_NEAR(linear.at(0.3).value, 130, 1e-12);  // softening slope −200 continued
  EXPECT_NEAR(linear.at(0.3).slope, -200, 1e-12);
}

TEST(HardeningIsotropic, OneRowTableIsPerfectPlasticity) {
  ConnectorPlasticity p;
  IsotropicHardening iso;
  iso.table = {point(100, 0)};
  p.isotropic = iso;
  const auto law = IsotropicHardeningLaw::from_plasticity(p);
  EXPECT_EQ(law.at(0.7).value, 100.0);
  EXPECT_EQ(law.at(0.7).slope, 0.0);
}

TEST(HardeningIsotropic, ExponentialLaw) {
  ConnectorPlasticity p;
  IsotropicHardening iso;
  iso.definition = IsotropicHardening::Definition::ExponentialLaw;
  iso.f0 = 100;
  iso.q_inf = 50;
  iso.b = 20;
  p.isotropic = iso;
  const auto law = IsotropicHardeningLaw::from_plasticity(p);
  const double u = 0.03;
  EXPECT_NEAR(law.at(u).value, 100 + 50 * (1 - std::exp(-0.6)), 1e-12);
  EXPECT_NEAR(law.at(u).slope, 1000 * std::exp(-0.6), 1e-12);
  EXPECT_NEAR(law.at(0).value, 100, 1e-12);
}

TEST(HardeningYieldSize, KinematicF0WithoutIsotropicAndIsotropicWinsOtherwise) {
  ConnectorPlasticity p;
  KinematicHardening k;
  k.f0 = 110;
  k.c = 500;
  p.kinematic = k;
  const auto kinematic_only = IsotropicHardeningLaw::from_plasticity(p);
  EXPECT_EQ(kinematic_only.at(0.3).value, 110.0);
  EXPECT_EQ(kinematic_only.at(0.3).slope, 0.0);
  IsotropicHardening iso;
  iso.table = {point(120, 0)};
  p.isotropic = iso;
  EXPECT_EQ(IsotropicHardeningLaw::from_plasticity(p).at(0.3).value, 120.0);  // §6.1
  EXPECT_THROW(IsotropicHardeningLaw::from_plasticity(ConnectorPlasticity{}),
               std::invalid_argument);
}

TEST(HardeningKinematic, ZieglerAndArmstrongFrederick) {
  const KinematicHardeningLaw ziegler{500, 0};
  EXPECT_NEAR(ziegler.back_force(30, -1, 0.02), 20, 1e-12);  // E8: α = 30 − 500·0.02
  EXPECT_EQ(ziegler.modulus(30, -1, 0.02), 500.0);
  const KinematicHardeningLaw af{2000, 20};
  const double dl = 0.1;
  EXPECT_NEAR(af.back_force(0, 1, dl), 200 / 3.0, 1e-12);
  EXPECT_NEAR(af.modulus(0, 1, dl), 2000 / 9.0, 1e-12);
  // H_α = s dα/dΔλ, checked by a central difference (truncation error O(δ²) ~ 1e-8).
  const double delta = 1e-6;
  const double fd = (af.back_force(50, -1, dl + delta) - af.back_force(50, -1, dl - delta)) /
                    (2 * delta);
  EXPECT_NEAR(-fd, af.modulus(50, -1, dl), 1e-6);
  // Saturation C/γ: a very large Δλ approaches 100 from either side.
  EXPECT_NEAR(af.back_force(-50, 1, 1e9), 100, 1e-6);
}

}  // namespace
}  // namespace clinch
