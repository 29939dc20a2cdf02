// SpringLaw (keywords.md §7): the CalculiX nonlinear spring deck ccx-spring2 read through the
// reader reproduces the force of its reference output; finite-difference tangents inside each
// table segment (behaviors.md §1.4 formula); constant force with zero tangent beyond the table;
// linear springs of either sign.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "tests/support/external_decks.hpp"
#include "base/jacobian_check.hpp"
#include "parser/deck_reader.hpp"
#include "src/behavior/elastic/spring_law.hpp"

namespace clinch {
namespace {

const std::string kDeckDir = std::string(CLINCH_SHARED_DIR) + "/external-decks/";

SpringProperty read_ccx_spring2() {
  SourceManager sources;
  Model model;
  DiagnosticSink sink;
  std::string io_error;
  EXPECT_EQ(read_deck_file(kDeckDir + "ccx-spring2.inp", sources, model, sink, &io_error),
            ReadStatus::Ok)
      << io_error;
  EXPECT_FALSE(sink.has_errors());
  EXPECT_EQ(model.sections.springs.size(), 1u);
  return model.sections.springs.empty() ? SpringProperty{} : model.sections.springs[0];
}

// U1 of node 2 as printed in the reference .dat (the spring elongation Δ, node 1 being fixed).
double reference_delta() {
  std::ifstream in(kDeckDir + "ccx-spring2.dat.ref");
  std::string line;
  double delta = NAN;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    int node = 0;
    double u1 = 0;
    if (fields >> node >> u1 && node == 2) delta = u1;
  }
  return delta;
}

// behaviors.md §1.4 for one scalar: central difference with h = 1e-6·max(|Δ|, u_s), u_s = 1e-3
// (no yield force), passing when |k' − k'_fd| ≤ 1e-5·|k'| + 1e-8·k_s.
void expect_fd_tangent(const SpringLaw& law, double delta, double k_s) {
  const double h = tangent_check_step(std::abs(delta), 1e-3);
  const auto force = [&law](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    f.setConstant(1, law.evaluate(x[0]).force);
    return true;
  };
  const JacobianReport report =
      check_jacobian(perturb_additively(force, Eigen::VectorXd::Constant(1, delta)),
                     Eigen::VectorXd::Constant(1, h),
                     Eigen::MatrixXd::Constant(1, 1, law.evaluate(delta).stiffness));
  EXPECT_TRUE(report.meets_tangent_rule(k_s)) << "Δ = " << delta << "\n" << report;
}

TEST(SpringLaw, CcxSpring2ReproducesTheReferenceForce) {
  CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS();
  const SpringProperty spring = read_ccx_spring2();
  ASSERT_TRUE(spring.valid);
  ASSERT_TRUE(spring.nonlinear);
  const SpringLaw law(spring);
  EXPECT_TRUE(law.nonlinear());
  const double delta = reference_delta();
  ASSERT_NEAR(delta, 1.211111, 1e-12);  // the printed value was found
  // The load is F = 11. Δ is printed with 7 significant digits (±5e-7) and the slope there is
  // (100 − 10)/(20 − 1) = 90/19, so F(printed Δ) may differ from 11 by up to 2.4e-6.
  const SpringResponse r = law.evaluate(delta);
  EXPECT_NEAR(r.force, 11.0, 0.5e-6 * 90.0 / 19.0);
  EXPECT_NEAR(r.stiffness, 90.0 / 19.0, 1e-14);
  EXPECT_FALSE(r.outside);
}

TEST(SpringLaw, FiniteDifferenceTangentInsideSegments) {
  CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS();
  const SpringLaw law(read_ccx_spring2());
  // Points away from the breakpoints 0, 1 and 20; k_s = 10, the largest slope of the table.
  for (double delta : {0.3, 0.9, 1.2111, 7.0, 19.5}) expect_fd_tangent(law, delta, 10.0);
  EXPECT_DOUBLE_EQ(law.evaluate(0.3).stiffness, 10.0);
  EXPECT_DOUBLE_EQ(law.evaluate(7.0).stiffness, 90.0 / 19.0);
}

TEST(SpringLaw, ConstantForceAndZeroTangentOutsideTheTable) {
  CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS();
  const SpringLaw law(read_ccx_spring2());
  const SpringResponse below = law.evaluate(-0.5);
  EXPECT_EQ(below.force, 0.0);
  EXPECT_EQ(below.stiffness, 0.0);
  EXPECT_TRUE(below.outside);
  const SpringResponse above = law.evaluate(25.0);
  EXPECT_EQ(above.force, 100.0);
  EXPECT_EQ(above.stiffness, 0.0);
  EXPECT_TRUE(above.outside);
  // The zero tangent is the true derivative there: the FD check passes with it.
  expect_fd_tangent(law, -0.5, 10.0);
  expect_fd_tangent(law, 25.0, 10.0);
}

TEST(SpringLaw, LinearSpringOfEitherSign) {
  for (double k : {1500.0, -3.5, 0.0}) {
    SpringProperty spring;
    spring.valid = true;
    spring.stiffness = k;
    const SpringLaw law(spring);
    EXPECT_FALSE(law.nonlinear());
    const SpringResponse r = law.evaluate(-0.02);
    EXPECT_DOUBLE_EQ(r.force, -0.02 * k);
    EXPECT_EQ(r.stiffness, k);
    EXPECT_FALSE(r.outside);
    expect_fd_tangent(law, -0.02, std::abs(k));
  }
}

TEST(SpringLaw, RejectsAnInvalidSpring) {
  SpringProperty spring;  // valid = false: validation did not accept it
  EXPECT_THROW(SpringLaw{spring}, std::invalid_argument);
}

}  // namespace
}  // namespace clinch
