// *RIGID BODY, *KINEMATIC COUPLING and *COUPLING (*KINEMATIC, *DISTRIBUTING) resolved into the
// flat lists the analysis eliminates (src/resolve/resolve_rigid_bodies.cpp, docs/constraints.md):
// which nodes follow which reference node in which DOFs, and the coefficients of the
// distributing couplings, computed by hand in the comments from the manual's formulas.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "parser/deck_reader.hpp"
#include "src/model/element_library.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

std::unique_ptr<CheckedDeck> read(const std::string& text) { return read_checked_deck(text); }

constexpr const char* kStep = "*STEP\n*STATIC\n*END STEP\n";

// A unit cube of one C3D8R (nodes 1-8), a reference node 10 at its centre and a connector from
// 10 to node 20.
constexpr const char* kCube =
    "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n5, 0, 0, 1\n6, 1, 0, 1\n"
    "7, 1, 1, 1\n8, 0, 1, 1\n10, .5, .5, .5\n20, 2, 0, 0\n"
    "*ELEMENT, TYPE=C3D8R, ELSET=BLOCK\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
    "*ELEMENT, TYPE=CONN3D2, ELSET=W\n2, 10, 20\n*CONNECTOR SECTION, ELSET=W\nBEAM\n";

// Global node index → label (flat decks: the labels in definition order).
std::int32_t label(const CheckedDeck& deck, std::int32_t n) {
  return deck.model.nodes[static_cast<std::size_t>(n)].label;
}

// label → (reference label, DOF mask) of every follower.
std::map<std::int32_t, std::pair<std::int32_t, DofMask>> followers(const CheckedDeck& deck) {
  std::map<std::int32_t, std::pair<std::int32_t, DofMask>> out;
  for (const NodeFollower& f : deck.model.constraints.followers) {
    EXPECT_TRUE(f.rigid_arm);
    out[label(deck, f.node)] = {label(deck, f.reference), f.dofs};
  }
  return out;
}

// The coefficient of (label, dof) in an equation, 0 when absent.
double coefficient(const CheckedDeck& deck, const LinearConstraint& equation, std::int32_t node,
                   int dof) {
  for (const LinearTerm& t : equation.terms) {
    if (label(deck, t.node) == node && t.dof == dof) return t.coefficient;
  }
  return 0.0;
}

// The equation whose first (eliminated) term is DOF `dof` of node `node`.
const LinearConstraint* equation_of(const CheckedDeck& deck, std::int32_t node, int dof) {
  for (const LinearConstraint& e : deck.model.constraints.equations) {
    if (label(deck, e.terms.at(0).node) == node && e.terms[0].dof == dof) return &e;
  }
  return nullptr;
}

TEST(RigidBodies, ElementNodesTieAndPinNodesFollowInTranslation) {
  auto deck = read(std::string(kCube) + "*NSET, NSET=PINS\n5\n"
                   "*RIGID BODY, REF NODE=10, ELSET=BLOCK, PIN NSET=PINS\n" + kStep);
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  auto f = followers(*deck);
  ASSERT_EQ(f.size(), 8u);
  for (std::int32_t n : {1, 2, 3, 4, 6, 7, 8}) EXPECT_EQ(f[n], std::make_pair(10, DofMask{0x3F}));
  EXPECT_EQ(f[5], std::make_pair(10, DofMask{0x07}));  // PIN NSET redefines it as a pin node
  ASSERT_EQ(deck->model.constraints.sources.size(), 1u);
  EXPECT_EQ(deck->model.constraints.sources[0].keyword, "*RIGID BODY");
  EXPECT_EQ(deck->model.constraints.sources[0].loc.line, 20u);
}

TEST(RigidBodies, TheReferenceNodeInItsOwnSetsIsLeftOut) {
  auto deck = read(std::string(kCube) + "*NSET, NSET=ALL\n1, 2, 10\n"
                   "*RIGID BODY, REF NODE=10, TIE NSET=ALL, ELSET=BLOCK\n" + kStep);
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  auto f = followers(*deck);
  EXPECT_EQ(f.size(), 8u);  // nodes 1 and 2 once, though in both TIE NSET and ELSET
  EXPECT_EQ(f.count(10), 0u);
}

TEST(RigidBodies, TwoDimensionalBodiesUseDofsOneTwoSix) {
  auto deck = read(
      "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n10, .5, .5\n20, 2, 0\n"
      "*ELEMENT, TYPE=CONN2D2, ELSET=W\n1, 10, 20\n*CONNECTOR SECTION, ELSET=W\nBEAM\n"
      "*NSET, NSET=T\n1, 2\n*NSET, NSET=P\n3\n"
      "*RIGID BODY, REF NODE=10, TIE NSET=T, PIN NSET=P\n" + std::string(kStep));
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  auto f = followers(*deck);
  EXPECT_EQ(f[1].second, DofMask{0x23});
  EXPECT_EQ(f[2].second, DofMask{0x23});
  EXPECT_EQ(f[3].second, DofMask{0x03});
}

// An ENCASTRE on tie node 1 (docs/constraints.md "Conditions on a body's nodes"): the body is
// anchored at node 1 in its translations (node 1 keeps them, the other nodes and the reference
// node 10 follow node 1 in them), and the rotations move to the reference node.
TEST(RigidBodies, AConditionOnATieNodeAnchorsTheBodyThere) {
  auto deck = read(std::string(kCube) + "*RIGID BODY, REF NODE=10, ELSET=BLOCK\n"
                   "*STEP\n*STATIC\n*BOUNDARY\n1, ENCASTRE\n*END STEP\n");
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  // (node, reference, anchor) → DOFs, by label (anchor 0: none).
  std::map<std::tuple<std::int32_t, std::int32_t, std::int32_t>, DofMask> follows;
  for (const NodeFollower& f : deck->model.constraints.followers) {
    follows[{label(*deck, f.node), label(*deck, f.reference),
             f.anchor < 0 ? 0 : label(*deck, f.anchor)}] |= f.dofs;
  }
  EXPECT_EQ(follows.size(), 1u + 1 + 2 * 7);
  EXPECT_EQ((follows[{1, 10, 0}]), DofMask{0x38});  // node 1 keeps its translations
  EXPECT_EQ((follows[{10, 10, 1}]), DofMask{0x07});
  for (std::int32_t n : {2, 3, 4, 5, 6, 7, 8}) {
    EXPECT_EQ((follows[{n, 10, 0}]), DofMask{0x38}) << n;
    EXPECT_EQ((follows[{n, 10, 1}]), DofMask{0x07}) << n;
  }
  // The line is split at its own location: translations at node 1, rotations at node 10.
  const auto& boundaries = deck->model.history.steps.at(0).boundaries;
  std::map<std::int32_t, DofMask> prescribed;
  for (const BoundaryCondition& bc : boundaries) {
    EXPECT_EQ(bc.loc.line, boundaries.front().loc.line);
    for (std::int32_t n : bc.resolved) prescribed[label(*deck, n)] |= bc.dofs;
  }
  EXPECT_EQ(prescribed, (std::map<std::int32_t, DofMask>{{1, 0x07}, {10, 0x38}}));
}

// A translation prescribed at two nodes of a body, or at its reference node and another, would
// fix the body's rotation: no anchoring, and E0523 at the second node's line.
TEST(RigidBodies, ATranslationPrescribedAtTwoNodesOfABodyIsRefused) {
  for (const char* second : {"2, 1, 1\n", "10, 1, 1\n"}) {
    auto deck = read(std::string(kCube) + "*RIGID BODY, REF NODE=10, ELSET=BLOCK\n"
                     "*BOUNDARY\n1, 1, 1\n" + second + kStep);
    for (const NodeFollower& f : deck->model.constraints.followers) EXPECT_LT(f.anchor, 0);
    EXPECT_FALSE(deck->with(DiagCode::dependent_dof_prescribed).empty()) << deck->dump();
  }
}

TEST(RigidBodies, CalculixRotNodeCarriesTheRotations) {
  auto deck = read(std::string(kCube) + "*NODE\n11, 0, 0, 0\n*NSET, NSET=N\n1, 2\n"
                   "*RIGID BODY, NSET=N, REF NODE=10, ROT NODE=11\n" + kStep);
  EXPECT_TRUE(deck->with(DiagCode::constraint_conflict).empty()) << deck->dump();
  EXPECT_EQ(followers(*deck).size(), 2u);
  for (int k = 1; k <= 3; ++k) {
    const LinearConstraint* e = equation_of(*deck, 10, 3 + k);
    ASSERT_NE(e, nullptr) << k;
    ASSERT_EQ(e->terms.size(), 2u);
    EXPECT_EQ(coefficient(*deck, *e, 10, 3 + k), 1.0);
    EXPECT_EQ(coefficient(*deck, *e, 11, k), -1.0);
    EXPECT_FALSE(e->exact_under_nlgeom);
  }
}

TEST(RigidBodies, AMissingRefNodeAndCenterOfMassAreRefusedAtTheirPlace) {
  auto deck = read(std::string(kCube) + "*RIGID BODY, ELSET=BLOCK\n"
                   "*RIGID BODY, REF NODE=10, ELSET=BLOCK, POSITION=CENTER OF MASS\n" + kStep);
  const Diagnostic& missing = deck->one(DiagCode::missing_parameter);
  EXPECT_EQ(missing.loc.line, 18u);
  EXPECT_NE(missing.message.find("REF NODE"), std::string::npos) << missing.message;
  const Diagnostic& position = deck->one(DiagCode::unsupported_option);
  EXPECT_EQ(position.loc.line, 19u);
  EXPECT_EQ(position.loc.column, 49u);  // the value CENTER OF MASS
}

TEST(RigidBodies, ANodeInTwoBodiesNamesBoth) {
  auto deck = read(std::string(kCube) + "*NODE\n11, 5, 5, 5\n*NSET, NSET=A\n1, 2\n"
                   "*NSET, NSET=B\n2, 3\n*RIGID BODY, REF NODE=10, TIE NSET=A\n"
                   "*RIGID BODY, REF NODE=11, PIN NSET=B\n*ELEMENT, TYPE=CONN3D2, ELSET=W2\n"
                   "3, 11, 20\n*CONNECTOR SECTION, ELSET=W2\nBEAM\n" + kStep);
  const Diagnostic& d = deck->one(DiagCode::constraint_conflict);
  EXPECT_EQ(d.loc.line, 25u);
  EXPECT_NE(d.message.find("node 2 is already constrained by another *RIGID BODY (DOFs 1, 2, 3)"),
            std::string::npos)
      << d.message;
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].loc.line, 24u);
}

TEST(RigidBodies, TheReferenceNodeOfOneBodyInAnotherIsAnError) {
  auto deck = read(std::string(kCube) + "*NODE\n11, 5, 5, 5\n*NSET, NSET=A\n1, 11\n"
                   "*NSET, NSET=B\n3\n*RIGID BODY, REF NODE=10, TIE NSET=A\n"
                   "*RIGID BODY, REF NODE=11, TIE NSET=B\n" + kStep);
  const Diagnostic& d = deck->one(DiagCode::constraint_conflict);
  EXPECT_EQ(d.loc.line, 25u);
  EXPECT_EQ(d.loc.column, 23u);  // REF NODE=11
  EXPECT_NE(d.message.find("reference node 11"), std::string::npos) << d.message;
}

// A *RIGID BODY written inside a part holds for each instance: two instances, two bodies, each
// with its own reference node (input-syntax.md §7).
TEST(RigidBodies, APartLevelBodyHoldsForEachInstance) {
  auto deck = read(
      "*PART, NAME=P\n*NODE\n1, 0.\n2, 1.\n3, 1., 1.\n4, 0., 1.\n10, .5, .5, 1.\n"
      "*ELEMENT, TYPE=R3D4, ELSET=SKIN\n1, 1, 2, 3, 4\n"
      "*RIGID BODY, REF NODE=10, ELSET=SKIN\n*END PART\n"
      "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=I1, PART=P\n*END INSTANCE\n"
      "*INSTANCE, NAME=I2, PART=P\n5., 0., 0.\n*END INSTANCE\n*END ASSEMBLY\n" +
      std::string(kStep));
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const auto& followers = deck->model.constraints.followers;
  ASSERT_EQ(followers.size(), 8u);
  for (const NodeFollower& f : followers) {
    const Node& node = deck->model.nodes[static_cast<std::size_t>(f.node)];
    const Node& reference = deck->model.nodes[static_cast<std::size_t>(f.reference)];
    EXPECT_EQ(reference.label, 10);
    EXPECT_EQ(reference.instance, node.instance);  // each copy follows its own reference node
    EXPECT_EQ(f.dofs, DofMask{0x3F});
  }
  EXPECT_EQ(deck->model.constraints.rigid_bodies[0].elements.size(), 2u);
}

TEST(Couplings, KinematicCouplingLinesGiveTheirDofs) {
  auto deck = read(std::string(kCube) + "*NSET, NSET=TOP\n5, 6\n"
                   "*KINEMATIC COUPLING, REF NODE=10\nTOP, 1, 3\n7, 4\n5, 6, 6\n" + kStep);
  // The cube is not a rigid body here: its block alone is refused.
  EXPECT_EQ(deck->sink.diagnostics().size(), 1u) << deck->dump();
  deck->one(DiagCode::deformable_element);
  auto f = followers(*deck);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[5].second, DofMask{0x27});  // DOFs 1-3 and 6 (two lines)
  EXPECT_EQ(f[6].second, DofMask{0x07});
  EXPECT_EQ(f[7].second, DofMask{0x08});
}

TEST(Couplings, OrientationIsAcceptedOnlyForWholeGroupsOfDofs) {
  auto deck = read(std::string(kCube) +
                   "*ORIENTATION, NAME=O\n1, 0, 0, 0, 1, 0\n"
                   "*KINEMATIC COUPLING, REF NODE=10, ORIENTATION=O\n1, 1, 3\n2, 1, 3\n"
                   "*KINEMATIC COUPLING, REF NODE=10, ORIENTATION=O\n3, 1, 2\n" + kStep);
  const Diagnostic& d = deck->one(DiagCode::unsupported_option);
  EXPECT_EQ(d.loc.line, 23u);
  EXPECT_EQ(followers(*deck).size(), 2u);
}

// *COUPLING with *KINEMATIC on a node-based surface (INFLUENCE RADIUS 0.9 from node 10 at
// (.5, .5, .5) keeps the nodes at distance √0.75 ≈ 0.866: all eight) and on the face S1 of the
// C3D8R (nodes 1, 2, 3, 4 in the manual's face numbering).
TEST(Couplings, KinematicSurfacesGiveTheirNodes) {
  auto deck = read(std::string(kCube) + "*NODE\n30, 9, 9, 9\n*NSET, NSET=ALL\n1, 2, 3, 4, 5, 6, 7, 8, 30\n"
                   "*SURFACE, NAME=SN, TYPE=NODE\nALL\n"
                   "*COUPLING, CONSTRAINT NAME=C1, REF NODE=10, SURFACE=SN, INFLUENCE RADIUS=.9\n"
                   "*KINEMATIC\n1, 3\n" + kStep);
  auto f = followers(*deck);
  EXPECT_EQ(f.size(), 8u) << deck->dump();
  EXPECT_EQ(f.count(30), 0u);
  EXPECT_EQ(f[1].second, DofMask{0x07});

  auto faces = read(std::string(kCube) + "*SURFACE, NAME=BOTTOM\nBLOCK, S1\n"
                    "*COUPLING, CONSTRAINT NAME=C2, REF NODE=10, SURFACE=BOTTOM\n*KINEMATIC\n" +
                    kStep);
  auto g = followers(*faces);
  ASSERT_EQ(g.size(), 4u) << faces->dump();
  for (std::int32_t n : {1, 2, 3, 4}) EXPECT_EQ(g[n].second, DofMask{0x3F}) << n;
}

// Uniform weights on the square (±1, ±1, 0) with the reference node at (0, 0, 1): ŵ = 1/4,
// x̄ = 0, r_n = (±1, ±1, 0), T = Σ ŵ (|r|² I − r rᵀ) = diag(1, 1, 2), r_R = (0, 0, 1).
//   Θ1 = Σ r_y u_z / 4, Θ2 = −Σ r_x u_z / 4, Θ3 = Σ (r_x u_y − r_y u_x) / 8,
//   u_R = ū + Θ × r_R = (ū1 + Θ2, ū2 − Θ1, ū3).
// So the equation of u_R1 holds −1/4 on u_x of each node and +r_x/4 on its u_z; that of θ_R3
// −r_x/8 on u_y and +r_y/8 on u_x. Tolerance 1e-15: a few roundings of numbers near 1.
TEST(Couplings, DistributingUniformWeightsAndTheOffsetReferenceNode) {
  auto deck = read(
      "*NODE\n1, 1, 1, 0\n2, -1, 1, 0\n3, -1, -1, 0\n4, 1, -1, 0\n10, 0, 0, 1\n20, 0, 0, 3\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=W\n1, 10, 20\n*CONNECTOR SECTION, ELSET=W\nBEAM\n"
      "*NSET, NSET=SQ\n1, 2, 3, 4\n*SURFACE, NAME=S, TYPE=NODE\nSQ\n"
      "*COUPLING, CONSTRAINT NAME=D, REF NODE=10, SURFACE=S\n*DISTRIBUTING\n1, 6\n" +
      std::string(kStep));
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  EXPECT_TRUE(deck->model.constraints.followers.empty());
  ASSERT_EQ(deck->model.constraints.equations.size(), 6u);
  const double rx[] = {1, -1, -1, 1}, ry[] = {1, 1, -1, -1};
  const LinearConstraint* u1 = equation_of(*deck, 10, 1);
  const LinearConstraint* u2 = equation_of(*deck, 10, 2);
  const LinearConstraint* u3 = equation_of(*deck, 10, 3);
  const LinearConstraint* t3 = equation_of(*deck, 10, 6);
  ASSERT_TRUE(u1 && u2 && u3 && t3);
  EXPECT_FALSE(u1->exact_under_nlgeom);
  for (int i = 0; i < 4; ++i) {
    const int n = i + 1;
    EXPECT_NEAR(coefficient(*deck, *u1, n, 1), -0.25, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *u1, n, 3), rx[i] / 4, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *u1, n, 2), 0.0, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *u2, n, 2), -0.25, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *u2, n, 3), ry[i] / 4, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *u3, n, 3), -0.25, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *u3, n, 1), 0.0, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *t3, n, 2), -rx[i] / 8, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *t3, n, 1), ry[i] / 8, 1e-15);
  }
}

// LINEAR weights with INFLUENCE RADIUS=4 and the reference node at the origin: nodes A (1, 0, 0)
// and B (−1, 0, 0) at r = 1 weigh 1 − 1/4 = .75, C (0, 2, 0) and D (0, −2, 0) at r = 2 weigh .5;
// normalised .3, .3, .2, .2. x̄ = 0 = x_R. Σ ŵ r rᵀ = diag(.6, 1.6, 0), Σ ŵ |r|² = 2.2, so
// T = diag(1.6, .6, 2.2) and
//   u_R1 = .3 (u_A1 + u_B1) + .2 (u_C1 + u_D1),
//   θ_R1 = (.4 u_C3 − .4 u_D3) / 1.6 = .25 u_C3 − .25 u_D3,
//   θ_R2 = (−.3 u_A3 + .3 u_B3) / .6 = −.5 u_A3 + .5 u_B3,
//   θ_R3 = (.3 u_A2 − .3 u_B2 − .4 u_C1 + .4 u_D1) / 2.2.
// Tolerance 1e-14: a few roundings of numbers of order 1.
TEST(Couplings, DistributingLinearWeights) {
  auto deck = read(
      "*NODE\n1, 1, 0, 0\n2, -1, 0, 0\n3, 0, 2, 0\n4, 0, -2, 0\n10, 0, 0, 0\n20, 0, 0, 3\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=W\n1, 10, 20\n*CONNECTOR SECTION, ELSET=W\nBEAM\n"
      "*NSET, NSET=X\n1, 2, 3, 4\n*SURFACE, NAME=S, TYPE=NODE\nX\n"
      "*COUPLING, CONSTRAINT NAME=D, REF NODE=10, SURFACE=S, INFLUENCE RADIUS=4\n"
      "*DISTRIBUTING, WEIGHTING METHOD=LINEAR\n" +
      std::string(kStep));
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const LinearConstraint* u1 = equation_of(*deck, 10, 1);
  const LinearConstraint* t1 = equation_of(*deck, 10, 4);
  const LinearConstraint* t2 = equation_of(*deck, 10, 5);
  const LinearConstraint* t3 = equation_of(*deck, 10, 6);
  ASSERT_TRUE(u1 && t1 && t2 && t3) << deck->dump();
  EXPECT_NEAR(coefficient(*deck, *u1, 1, 1), -0.3, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *u1, 2, 1), -0.3, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *u1, 3, 1), -0.2, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *u1, 4, 1), -0.2, 1e-14);
  EXPECT_EQ(u1->terms.size(), 5u);  // no offset: no rotation terms
  EXPECT_NEAR(coefficient(*deck, *t1, 3, 3), -0.25, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *t1, 4, 3), 0.25, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *t2, 1, 3), 0.5, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *t2, 2, 3), -0.5, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *t3, 1, 2), -0.3 / 2.2, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *t3, 2, 2), 0.3 / 2.2, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *t3, 3, 1), 0.4 / 2.2, 1e-14);
  EXPECT_NEAR(coefficient(*deck, *t3, 4, 1), -0.4 / 2.2, 1e-14);
}

// Two dimensions (a CONN2D2 makes the model 2-D): u1, u2 and θ3 only. Uniform weights on A (1, 0),
// B (−1, 0), C (0, 1), D (0, −1), reference node R at (0, 2): ŵ = 1/4, x̄ = 0, T33 = Σ ŵ |r|² = 1,
//   θ = (u_A2 − u_B2 − u_C1 + u_D1) / 4,  u_R = ū + θ e3 × r_R = (ū1 − 2θ, ū2).
// So u_R1 = .25 u_A1 − .5 u_A2 + .25 u_B1 + .5 u_B2 + .75 u_C1 − .25 u_D1 (terms: the negatives).
// Tolerance 1e-15: a few roundings of numbers of order 1.
TEST(Couplings, DistributingInTwoDimensions) {
  auto deck = read(
      "*NODE\n1, 1, 0\n2, -1, 0\n3, 0, 1\n4, 0, -1\n10, 0, 2\n20, 0, 3\n"
      "*ELEMENT, TYPE=CONN2D2, ELSET=W\n1, 10, 20\n*CONNECTOR SECTION, ELSET=W\nBEAM\n"
      "*NSET, NSET=X\n1, 2, 3, 4\n*SURFACE, NAME=S, TYPE=NODE\nX\n"
      "*COUPLING, CONSTRAINT NAME=D, REF NODE=10, SURFACE=S\n*DISTRIBUTING\n" +
      std::string(kStep));
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  ASSERT_EQ(deck->model.constraints.equations.size(), 3u);  // u1, u2, θ3
  const LinearConstraint* u1 = equation_of(*deck, 10, 1);
  const LinearConstraint* u2 = equation_of(*deck, 10, 2);
  const LinearConstraint* t3 = equation_of(*deck, 10, 6);
  ASSERT_TRUE(u1 && u2 && t3);
  const std::pair<std::pair<int, int>, double> expected_u1[] = {
      {{1, 1}, -0.25}, {{1, 2}, 0.5}, {{2, 1}, -0.25}, {{2, 2}, -0.5},
      {{3, 1}, -0.75}, {{3, 2}, 0.0}, {{4, 1}, 0.25},  {{4, 2}, 0.0}};
  for (const auto& [term, value] : expected_u1) {
    EXPECT_NEAR(coefficient(*deck, *u1, term.first, term.second), value, 1e-15)
        << term.first << "." << term.second;
  }
  for (int n = 1; n <= 4; ++n) {
    EXPECT_NEAR(coefficient(*deck, *u2, n, 2), -0.25, 1e-15);
    EXPECT_NEAR(coefficient(*deck, *u2, n, 1), 0.0, 1e-15);
  }
  EXPECT_NEAR(coefficient(*deck, *t3, 1, 2), -0.25, 1e-15);
  EXPECT_NEAR(coefficient(*deck, *t3, 2, 2), 0.25, 1e-15);
  EXPECT_NEAR(coefficient(*deck, *t3, 3, 1), 0.25, 1e-15);
  EXPECT_NEAR(coefficient(*deck, *t3, 4, 1), -0.25, 1e-15);
  for (const LinearConstraint& e : deck->model.constraints.equations) {
    for (const LinearTerm& t : e.terms) EXPECT_TRUE(t.dof == 1 || t.dof == 2 || t.dof == 6);
  }
}

TEST(Couplings, CollinearNodesCannotCarryRotations) {
  auto deck = read(
      "*NODE\n1, 1, 0, 0\n2, -1, 0, 0\n10, 0, 0, 0\n20, 0, 0, 3\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=W\n1, 10, 20\n*CONNECTOR SECTION, ELSET=W\nBEAM\n"
      "*NSET, NSET=X\n1, 2\n*SURFACE, NAME=S, TYPE=NODE\nX\n"
      "*COUPLING, CONSTRAINT NAME=LINE, REF NODE=10, SURFACE=S\n*DISTRIBUTING\n1, 6\n" +
      std::string(kStep));
  const Diagnostic& d = deck->one(DiagCode::degenerate_coupling);
  EXPECT_EQ(d.loc.line, 14u);
  EXPECT_NE(d.message.find("*COUPLING 'LINE'"), std::string::npos) << d.message;
  // Translations alone with the reference node at the centroid need no rotation.
  auto translations = read(
      "*NODE\n1, 1, 0, 0\n2, -1, 0, 0\n10, 0, 0, 0\n20, 0, 0, 3\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=W\n1, 10, 20\n*CONNECTOR SECTION, ELSET=W\nBEAM\n"
      "*NSET, NSET=X\n1, 2\n*SURFACE, NAME=S, TYPE=NODE\nX\n"
      "*COUPLING, CONSTRAINT NAME=LINE, REF NODE=10, SURFACE=S\n*DISTRIBUTING\n1, 3\n" +
      std::string(kStep));
  EXPECT_TRUE(translations->sink.diagnostics().empty()) << translations->dump();
  EXPECT_EQ(translations->model.constraints.equations.size(), 3u);
}

TEST(Couplings, AKinematicCouplingNodeOfARigidBodyIsTiedTwice) {
  auto deck = read(std::string(kCube) + "*RIGID BODY, REF NODE=10, ELSET=BLOCK\n"
                   "*NODE\n11, 3, 3, 3\n*KINEMATIC COUPLING, REF NODE=11\n1, 1, 1\n" + kStep);
  const Diagnostic& d = deck->one(DiagCode::constraint_conflict);
  EXPECT_EQ(d.loc.line, 21u);
  EXPECT_NE(d.message.find("node 1 is already constrained by a *RIGID BODY (DOF 1)"),
            std::string::npos)
      << d.message;
}

// The face nodes of the manual's element library ("Three-dimensional solid element library",
// face numbering; shells: SPOS/SNEG hold every node), typed from its tables.
TEST(Couplings, FaceNodesFollowTheManualsNumbering) {
  const std::pair<std::pair<const char*, const char*>, std::vector<int>> cases[] = {
      {{"C3D4", "S3"}, {2, 4, 3}},
      {{"C3D10", "S3"}, {2, 4, 3, 9, 10, 6}},
      {{"C3D6", "S2"}, {4, 6, 5}},
      {{"C3D6", "S4"}, {2, 5, 6, 3}},
      {{"C3D8R", "S5"}, {3, 7, 8, 4}},
      {{"C3D20", "S2"}, {5, 8, 7, 6, 16, 15, 14, 13}},
      {{"S4R", "SPOS"}, {1, 2, 3, 4}},
      {{"R3D3", "SNEG"}, {1, 2, 3}},
      {{"C3D15", "S1"}, {}},
      {{"C3D8", "SPOS"}, {}},
      {{"R2D2", "SPOS"}, {}},
  };
  for (const auto& [key, nodes] : cases) {
    const ElementTypeInfo* info = find_element_type(key.first);
    ASSERT_NE(info, nullptr) << key.first;
    auto found = face_node_positions(*info, key.second);
    EXPECT_EQ(std::vector<int>(found.begin(), found.end()), nodes) << key.first << " " << key.second;
  }
}

}  // namespace
}  // namespace clinch
