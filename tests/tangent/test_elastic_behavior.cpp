// Elastic connector behaviour (behaviors.md §4): finite-difference tangent checks (§1.4, §4.7)
// for linear, nonlinear (inside each segment and in both extrapolated ranges) and coupled
// elasticity; the forces of worked examples E2 (CONSTANT and LINEAR extrapolation) and E3
// (coupled) from decks read through the reader; RIGID components and when no law is built.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"
#include "src/behavior/elastic/elastic_behavior.hpp"
#include "tests/tangent/behavior_tangent_check.hpp"

namespace clinch {
namespace {

struct Evaluation {
  IntegrationStatus status;
  BehaviorOutput out;
};

// Integrates from the committed motion `old` to the trial motion `u` (no history: §4.6).
Evaluation integrate(const Behavior& law, const Vector6& old, const Vector6& u,
                     TangentRequest tangent = TangentRequest::Consistent) {
  const Vector6 increment = u - old;
  const BehaviorInput in{old, increment, 0.0, 0.0, {}, tangent};
  Evaluation e{IntegrationStatus::Failure, {}};
  e.status = law.integrate(in, e.out);
  return e;
}

// §1.4 with u_s = 1e-3 (elasticity has no yield force), every evaluation from the same
// committed state.
void expect_fd_tangent(const Behavior& law, const Vector6& old, const Vector6& u, double k_s) {
  const Evaluation at = integrate(law, old, u);
  ASSERT_EQ(at.status, IntegrationStatus::Success);
  const auto force = [&](const Eigen::VectorXd& x, Eigen::VectorXd& f) {
    const Evaluation e = integrate(law, old, Vector6(x));
    f = e.out.force;
    return e.status == IntegrationStatus::Success;
  };
  expect_fd_tangent_rule(force, u, at.out.tangent, 1e-3, k_s);
}

Vector6 motion(double u1, double u2 = 0, double u3 = 0, double u4 = 0, double u5 = 0,
               double u6 = 0) {
  Vector6 u;
  u << u1, u2, u3, u4, u5, u6;
  return u;
}

ConnectorElasticity linear(int component, double k) {
  ConnectorElasticity e;
  e.kind = ConnectorElasticity::Kind::Linear;
  e.component = component;
  e.stiffness = k;
  return e;
}

// §4.5 E2 table: force at motion (-0.1, -100), (0, 0), (0.1, 100), (0.2, 150).
ConnectorElasticity e2_nonlinear(int component, Extrapolation extrapolation) {
  ConnectorElasticity e;
  e.kind = ConnectorElasticity::Kind::Nonlinear;
  e.component = component;
  e.extrapolation = extrapolation;
  for (auto [f, u] : {std::pair{-100.0, -0.1}, {0.0, 0.0}, {100.0, 0.1}, {150.0, 0.2}}) {
    TablePoint p;
    p.value = f;
    p.at = u;
    e.table.push_back(p);
  }
  return e;
}

ConnectorElasticity rigid(ComponentMask components, bool all) {
  ConnectorElasticity e;
  e.kind = ConnectorElasticity::Kind::Rigid;
  e.rigid_components = components;
  e.rigid_all = all;
  return e;
}

ConnectorBehavior behavior_of(std::vector<ConnectorElasticity> elasticities) {
  ConnectorBehavior b;
  b.elasticities = std::move(elasticities);
  return b;
}

constexpr ComponentMask kAll = 0b111111;

// Committed motions the trial states start from; elasticity must not depend on them, so any
// values do, as long as the sum old + increment is what counts.
const Vector6 kOld = motion(0.01, -0.02, 0.03, 0.004, -0.005, 0.006);

// ------------------------------------------------------------------------ linear (§4.1)

TEST(ElasticBehavior, LinearUncoupledForcesAndTangent) {
  const auto law = make_elastic_behavior(behavior_of({linear(1, 1000.0), linear(3, 250.0)}), kAll);
  ASSERT_NE(law, nullptr);
  EXPECT_EQ(law->components(), 0b101);
  EXPECT_EQ(law->history_size(), 0);
  EXPECT_TRUE(law->tangent_is_symmetric());
  const Evaluation e = integrate(*law, kOld, motion(0.2, 0.5, -0.04, 0.1, 0.1, 0.1));
  EXPECT_EQ(e.status, IntegrationStatus::Success);
  // Exact products of short decimals: 1e-12 covers their rounding.
  EXPECT_NEAR(e.out.force[0], 200.0, 1e-12);
  EXPECT_NEAR(e.out.force[2], -10.0, 1e-12);
  for (int i : {1, 3, 4, 5}) EXPECT_EQ(e.out.force[i], 0.0) << "slot " << i;
  Matrix6 expected = Matrix6::Zero();
  expected(0, 0) = 1000.0;
  expected(2, 2) = 250.0;
  EXPECT_EQ(e.out.tangent, expected);
}

// §2: definitions on one component add: two linear ones and a NONLINEAR table on component 1,
// f1 = (1000 + 500)·u1 + table(u1) with the E2 table, and the tangent likewise.
TEST(ElasticBehavior, DefinitionsOnAComponentAdd) {
  const auto law = make_elastic_behavior(
      behavior_of({linear(1, 1000.0), linear(1, 500.0), e2_nonlinear(1, Extrapolation::Linear)}),
      kAll);
  ASSERT_NE(law, nullptr);
  const Evaluation e = integrate(*law, kOld, motion(0.15));
  EXPECT_NEAR(e.out.force[0], 1500.0 * 0.15 + 125.0, 1e-12);
  EXPECT_NEAR(e.out.tangent(0, 0), 1500.0 + 500.0, 1e-12);
  expect_fd_tangent(*law, kOld, motion(0.15, 0.01), 2000.0);
}

TEST(ElasticBehavior, LinearUncoupledFiniteDifferenceTangent) {
  const auto law = make_elastic_behavior(
      behavior_of({linear(1, 1000.0), linear(2, 50.0), linear(6, 3.0e4)}), kAll);
  ASSERT_NE(law, nullptr);
  for (const Vector6& u : {motion(0.2, -0.1, 0.0, 0.0, 0.0, 0.3), motion(-1e-4, 2e-5),
                           motion(5.0, 0.0, 0.0, 0.0, 0.0, -2.0)}) {
    expect_fd_tangent(*law, kOld, u, 3.0e4);
  }
}

TEST(ElasticBehavior, OutputSlotsItDoesNotActOnAreZeroed) {
  const auto law = make_elastic_behavior(behavior_of({linear(2, 10.0)}), kAll);
  ASSERT_NE(law, nullptr);
  const Vector6 increment = motion(1, 1, 1, 1, 1, 1);
  const BehaviorInput in{kOld, increment, 0.0, 0.0, {}, TangentRequest::Consistent};
  BehaviorOutput out;
  out.force.setConstant(7.0);  // left over from another element
  out.tangent.setConstant(7.0);
  ASSERT_EQ(law->integrate(in, out), IntegrationStatus::Success);
  EXPECT_EQ(out.force, motion(0, 10.0 * (kOld[1] + 1.0)));
  Matrix6 expected = Matrix6::Zero();
  expected(1, 1) = 10.0;
  EXPECT_EQ(out.tangent, expected);
}

TEST(ElasticBehavior, NoTangentRequestedLeavesTangentUntouched) {
  const auto law = make_elastic_behavior(behavior_of({linear(1, 10.0)}), kAll);
  ASSERT_NE(law, nullptr);
  const Evaluation e = integrate(*law, kOld, motion(0.5), TangentRequest::None);
  EXPECT_NEAR(e.out.force[0], 5.0, 1e-15);
  EXPECT_EQ(e.out.tangent, Matrix6::Zero());
}

// ------------------------------------------------------------------------ nonlinear (§4.2)

TEST(ElasticBehavior, NonlinearFiniteDifferenceTangentInEverySegment) {
  // Inside each segment and in both extrapolated ranges, away from the breakpoints
  // −0.1, 0, 0.1, 0.2 (§4.7). k_s = 1000, the largest slope.
  for (Extrapolation x : {Extrapolation::Constant, Extrapolation::Linear}) {
    const auto law = make_elastic_behavior(behavior_of({e2_nonlinear(1, x)}), kAll);
    ASSERT_NE(law, nullptr);
    EXPECT_EQ(law->components(), 0b1);
    for (double u1 : {-0.3, -0.05, 0.05, 0.15, 0.35}) {
      SCOPED_TRACE(u1);
      expect_fd_tangent(*law, kOld, motion(u1), 1000.0);
    }
  }
}

TEST(ElasticBehavior, NonlinearTangentIsTheSegmentSlope) {
  const auto constant =
      make_elastic_behavior(behavior_of({e2_nonlinear(2, Extrapolation::Constant)}), kAll);
  const auto linear_x =
      make_elastic_behavior(behavior_of({e2_nonlinear(2, Extrapolation::Linear)}), kAll);
  ASSERT_NE(constant, nullptr);
  ASSERT_NE(linear_x, nullptr);
  // Below the table: CONSTANT holds −100 with slope 0, LINEAR continues −100 + 1000 (u + 0.1).
  EXPECT_EQ(integrate(*constant, kOld, motion(0, -0.3)).out.tangent(1, 1), 0.0);
  EXPECT_EQ(integrate(*constant, kOld, motion(0, -0.3)).out.force[1], -100.0);
  EXPECT_EQ(integrate(*linear_x, kOld, motion(0, -0.3)).out.tangent(1, 1), 1000.0);
  EXPECT_NEAR(integrate(*linear_x, kOld, motion(0, -0.3)).out.force[1], -300.0, 1e-9);
  // At a breakpoint, the right-hand segment (§4.2).
  EXPECT_EQ(integrate(*constant, kOld, motion(0, 0.1)).out.tangent(1, 1), 500.0);
}

// §4.5 E2 on a deck read through the reader: the behaviour's EXTRAPOLATION (§1.2 precedence)
// reaches the law. Forces at the four increments, U = 0.3 applied in steps of 0.075.
std::string e2_deck(const std::string& behavior_parameters) {
  return "*NODE\n1, 0., 0., 0.\n2, 10., 0., 0.\n"
         "*ELEMENT, TYPE=CONN3D2, ELSET=CONN\n1, 1, 2\n"
         "*CONNECTOR SECTION, ELSET=CONN, BEHAVIOR=B\nAXIAL,\n"
         "*CONNECTOR BEHAVIOR, NAME=B" +
         behavior_parameters +
         "\n*CONNECTOR ELASTICITY, COMPONENT=1, NONLINEAR\n"
         "-100., -0.1\n0., 0.\n100., 0.1\n150., 0.2\n"
         "*BOUNDARY\n1, 1, 3\n2, 2, 3\n"
         "*STEP\n*STATIC, DIRECT\n0.25, 1.0\n*BOUNDARY\n2, 1, 1, 0.3\n*END STEP\n";
}

struct ReadDeck {
  SourceManager sources;
  Model model;
  DiagnosticSink sink;
  std::string listing() const {
    std::string out;
    for (const Diagnostic& d : sink.diagnostics()) out += render_text(d, sources);
    return out;
  }
};

std::unique_ptr<ReadDeck> read(const std::string& text) {
  auto r = std::make_unique<ReadDeck>();
  read_deck_text("deck.inp", text, r->sources, r->model, r->sink);
  return r;
}

struct E2Row {
  double u, constant_force, constant_tangent, linear_force, linear_tangent;
};

TEST(ElasticBehavior, WorkedExampleE2BothExtrapolations) {
  const E2Row rows[] = {{0.075, 75, 1000, 75, 1000},
                        {0.15, 125, 500, 125, 500},
                        {0.225, 150, 0, 162.5, 500},
                        {0.3, 150, 0, 200, 500}};
  for (bool linear_x : {false, true}) {
    SCOPED_TRACE(linear_x ? "EXTRAPOLATION=LINEAR" : "default CONSTANT");
    auto deck = read(e2_deck(linear_x ? ", EXTRAPOLATION=LINEAR" : ""));
    ASSERT_FALSE(deck->sink.has_errors()) << deck->listing();
    const ConnectorSection& section = deck->model.sections.connector_sections.at(0);
    EXPECT_EQ(section.available, 0b1);
    const auto law =
        make_elastic_behavior(deck->model.behaviors.behaviors.at(0), section.available);
    ASSERT_NE(law, nullptr);
    Vector6 old = Vector6::Zero();
    for (const E2Row& row : rows) {
      const Vector6 u = motion(row.u);
      const Evaluation e = integrate(*law, old, u);
      // One interpolation of O(100) values at motions that are short decimals: 1e-9 covers the
      // rounding of 0.075 etc. times slopes of 1000.
      EXPECT_NEAR(e.out.force[0], linear_x ? row.linear_force : row.constant_force, 1e-9)
          << "u = " << row.u;
      EXPECT_EQ(e.out.tangent(0, 0), linear_x ? row.linear_tangent : row.constant_tangent)
          << "u = " << row.u;
      old = u;  // the increment converged
    }
  }
}

TEST(ElasticBehavior, LinearAndNonlinearComponentsTogether) {
  const auto law = make_elastic_behavior(
      behavior_of({linear(1, 1000.0), e2_nonlinear(4, Extrapolation::Linear)}), kAll);
  ASSERT_NE(law, nullptr);
  EXPECT_EQ(law->components(), 0b1001);
  const Evaluation e = integrate(*law, kOld, motion(0.01, 0, 0, 0.15));
  EXPECT_NEAR(e.out.force[0], 10.0, 1e-12);
  EXPECT_NEAR(e.out.force[3], 125.0, 1e-9);
  expect_fd_tangent(*law, kOld, motion(0.01, 0.3, 0.3, 0.15, 0.3, 0.3), 1000.0);
}

// ------------------------------------------------------------------------ coupled (§4.3)

TEST(ElasticBehavior, WorkedExampleE3Coupled) {
  auto deck = read(
      "*NODE\n1, 0., 0., 0.\n2, 0., 0., 0.\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=CONN\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=CONN, BEHAVIOR=B\nCARTESIAN,\n"
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY\n"
      "1000., 200., 500., 0., 0., 800., 0., 0.\n"
      "0., 0., 0., 0., 0., 0., 0., 0.\n"
      "0., 0., 0., 0., 0.\n"
      "*BOUNDARY\n1, ENCASTRE\n"
      "*STEP\n*STATIC\n*BOUNDARY\n2, 1, 1, 0.01\n2, 2, 2, 0.02\n2, 3, 3, 0.\n*END STEP\n");
  ASSERT_FALSE(deck->sink.has_errors()) << deck->listing();
  const ConnectorSection& section = deck->model.sections.connector_sections.at(0);
  EXPECT_EQ(section.available, 0b111);
  const auto law = make_elastic_behavior(deck->model.behaviors.behaviors.at(0), section.available);
  ASSERT_NE(law, nullptr);
  EXPECT_EQ(law->components(), 0b111);
  const Evaluation e = integrate(*law, Vector6::Zero(), motion(0.01, 0.02, 0.0));
  // f1 = 1000·0.01 + 200·0.02 = 14, f2 = 200·0.01 + 500·0.02 = 12, f3 = 0; sums of two
  // rounded products: 1e-12.
  EXPECT_NEAR(e.out.force[0], 14.0, 1e-12);
  EXPECT_NEAR(e.out.force[1], 12.0, 1e-12);
  EXPECT_EQ(e.out.force[2], 0.0);
  expect_fd_tangent(*law, kOld, motion(0.01, 0.02, 0.0), 1000.0);
}

// A full symmetric positive-definite D, restricted to the CONN2D2 components 1, 2, 6.
ConnectorBehavior full_coupled() {
  ConnectorElasticity e;
  e.kind = ConnectorElasticity::Kind::Coupled;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      e.coupled[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          i == j ? 1000.0 * (i + 1) : 10.0 * (i + j + 1);
    }
  }
  return behavior_of({e});
}

TEST(ElasticBehavior, CoupledFiniteDifferenceTangentEqualsSymmetricD) {
  const auto law = make_elastic_behavior(full_coupled(), kAll);
  ASSERT_NE(law, nullptr);
  EXPECT_TRUE(law->tangent_is_symmetric());
  const Vector6 u = motion(0.1, -0.2, 0.05, 0.3, -0.01, 0.02);
  const Evaluation e = integrate(*law, kOld, u);
  EXPECT_EQ(e.out.tangent, e.out.tangent.transpose());
  EXPECT_EQ(e.out.tangent(0, 1), 20.0);
  EXPECT_EQ(e.out.tangent(5, 5), 6000.0);
  expect_fd_tangent(*law, kOld, u, 6000.0);
  expect_fd_tangent(*law, kOld, motion(-3.0, 1.0, 0.0, 0.0, 2.0, 0.0), 6000.0);
}

TEST(ElasticBehavior, CoupledIsRestrictedToAvailableComponents) {
  constexpr ComponentMask kPlanar = 0b100011;  // CONN2D2: 1, 2, 6
  const auto law = make_elastic_behavior(full_coupled(), kPlanar);
  ASSERT_NE(law, nullptr);
  EXPECT_EQ(law->components(), kPlanar);
  const Vector6 u = motion(0.1, -0.2, 0.05, 0.3, -0.01, 0.02);
  const Evaluation e = integrate(*law, kOld, u);
  // f1 = 1000·0.1 + 20·(−0.2) + 60·0.02, with the 3–5 columns ignored.
  EXPECT_NEAR(e.out.force[0], 100.0 - 4.0 + 1.2, 1e-12);
  for (int i : {2, 3, 4}) {
    EXPECT_EQ(e.out.force[i], 0.0) << "slot " << i;
    EXPECT_EQ(e.out.tangent.row(i).cwiseAbs().maxCoeff(), 0.0) << "row " << i;
    EXPECT_EQ(e.out.tangent.col(i).cwiseAbs().maxCoeff(), 0.0) << "column " << i;
  }
  expect_fd_tangent(*law, kOld, u, 6000.0);
}

// ------------------------------------------------------------------------ RIGID and absence

TEST(ElasticBehavior, RigidComponentsAreNotPartOfTheLaw) {
  const ConnectorBehavior b = behavior_of({linear(1, 100.0), rigid(0b010, false)});
  EXPECT_EQ(rigid_components(b, kAll), 0b010);
  const auto law = make_elastic_behavior(b, kAll);
  ASSERT_NE(law, nullptr);
  EXPECT_EQ(law->components(), 0b001);
  EXPECT_EQ(make_elastic_behavior(behavior_of({rigid(0, true)}), kAll), nullptr);
}

TEST(ElasticBehavior, RigidComponentsFollowAvailability) {
  EXPECT_EQ(rigid_components(behavior_of({rigid(0, true)}), 0b100011), 0b100011);
  EXPECT_EQ(rigid_components(behavior_of({rigid(0b000101, false)}), 0b000011), 0b000001);
  EXPECT_EQ(rigid_components(behavior_of({linear(1, 1.0)}), kAll), 0);
}

TEST(ElasticBehavior, NoLawWithoutElasticityOnAnAvailableComponent) {
  EXPECT_EQ(make_elastic_behavior(behavior_of({}), kAll), nullptr);
  EXPECT_EQ(make_elastic_behavior(behavior_of({linear(4, 1.0)}), 0b000111), nullptr);
  EXPECT_EQ(make_elastic_behavior(full_coupled(), 0), nullptr);
}

}  // namespace
}  // namespace clinch
