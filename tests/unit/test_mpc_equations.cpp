// *MPC and *EQUATION resolved into the flat lists the analysis eliminates
// (src/resolve/resolve_mpc_equations.cpp), and the overconstraint checks over every constraint
// kind (src/check/constraint_checks.cpp; docs/constraints.md "MPCs", "Equations",
// "Overconstraints"). The expected lists are written out by hand from the manual's definitions:
// terms and coefficients are copied from the deck, so they compare exactly.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

std::unique_ptr<CheckedDeck> read(const std::string& text) { return read_checked_deck(text); }

constexpr const char* kStep = "*STEP\n*STATIC\n*END STEP\n";
constexpr const char* kNlgeomStep = "*STEP, NLGEOM=YES\n*STATIC\n*END STEP\n";

// Nodes 1-4 on the x axis, 5-8 one unit above them, 9 at (0, 0, 5); a connector keeps them in the
// analysis.
constexpr const char* kNodes =
    "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 2, 0, 0\n4, 3, 0, 0\n"
    "5, 0, 1, 0\n6, 1, 1, 0\n7, 2, 1, 0\n8, 3, 1, 0\n9, 0, 0, 5\n"
    "*ELEMENT, TYPE=CONN3D2, ELSET=W\n100, 1, 9\n*CONNECTOR SECTION, ELSET=W\nCARTESIAN,\n"
    "*NSET, NSET=BOTTOM\n1, 2, 3, 4\n*NSET, NSET=TOP\n5, 6, 7, 8\n*NSET, NSET=PAIR\n2, 3\n";

std::int32_t label(const CheckedDeck& deck, std::int32_t n) {
  return deck.model.nodes[static_cast<std::size_t>(n)].label;
}

// (node label, DOF, coefficient) of every term, equation by equation.
using Term = std::tuple<std::int32_t, int, double>;
std::vector<std::vector<Term>> equations(const CheckedDeck& deck) {
  std::vector<std::vector<Term>> out;
  for (const LinearConstraint& e : deck.model.constraints.equations) {
    EXPECT_TRUE(e.exact_under_nlgeom);
    std::vector<Term> terms;
    for (const LinearTerm& t : e.terms)
      terms.emplace_back(label(deck, t.node), t.dof, t.coefficient);
    out.push_back(std::move(terms));
  }
  return out;
}

struct FollowerView {
  std::int32_t reference;
  DofMask dofs;
  bool rigid_arm;
  bool operator==(const FollowerView&) const = default;
};
std::map<std::int32_t, FollowerView> followers(const CheckedDeck& deck) {
  std::map<std::int32_t, FollowerView> out;
  for (const NodeFollower& f : deck.model.constraints.followers) {
    out[label(deck, f.node)] = {label(deck, f.reference), f.dofs, f.rigid_arm};
  }
  return out;
}

// A deck that must be refused with one diagnostic of `code` at line:column, resolving to no
// constraint: kNodes, then `text`, then a step.
struct RefusalCase {
  const char* text;
  DiagCode code;
  std::uint32_t line, column;
};
void expect_refusals(std::initializer_list<RefusalCase> cases) {
  for (const RefusalCase& c : cases) {
    auto deck = read(std::string(kNodes) + c.text + kStep);
    const Diagnostic& d = deck->one(c.code);
    EXPECT_EQ(d.loc.line, c.line) << c.text << deck->dump();
    EXPECT_EQ(d.loc.column, c.column) << c.text << deck->dump();
    const ConstraintModel& constraints = deck->model.constraints;
    EXPECT_TRUE(constraints.equations.empty() && constraints.followers.empty() &&
                constraints.links.empty())
        << c.text;
  }
}

// ---- *EQUATION -------------------------------------------------------------------------------

TEST(Equations, TermsOverSeveralLinesAndTheNextEquation) {
  auto deck = read(std::string(kNodes) +
                   "*EQUATION\n5\n1, 1, 1.0, 2, 1, -0.5, 3, 1, -0.25, 4, 1, -0.125\n"
                   "5, 2, 2.5\n2\n6, 3, 1., 7, 3, -1.\n" +
                   kStep);
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const std::vector<std::vector<Term>> expected{
      {{1, 1, 1.0}, {2, 1, -0.5}, {3, 1, -0.25}, {4, 1, -0.125}, {5, 2, 2.5}},
      {{6, 3, 1.0}, {7, 3, -1.0}}};
  EXPECT_EQ(equations(*deck), expected);
  const ConstraintModel& c = deck->model.constraints;
  ASSERT_EQ(c.sources.size(), 2u);
  EXPECT_EQ(c.sources[0].keyword, "*EQUATION");
  EXPECT_EQ(c.sources[0].loc.line, 23u);  // the first term's line
  EXPECT_EQ(c.sources[1].loc.line, 26u);
  EXPECT_EQ(c.equations[1].source, 1);
}

TEST(Equations, NodeSetsExpandEntryByEntryAndASingleNodeRepeats) {
  // u1(1..4) − u1(5..8) + 0.5 u2(9) = 0, one equation per pair, node 9 in each.
  auto deck =
      read(std::string(kNodes) + "*EQUATION\n3\nBOTTOM, 1, 1., TOP, 1, -1., 9, 2, .5\n" + kStep);
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  std::vector<std::vector<Term>> expected;
  for (int k = 0; k < 4; ++k) expected.push_back({{1 + k, 1, 1.0}, {5 + k, 1, -1.0}, {9, 2, 0.5}});
  EXPECT_EQ(equations(*deck), expected);
  EXPECT_EQ(deck->model.constraints.sources.size(), 1u);
}

TEST(Equations, SetsOfDifferentSizesAreRefusedAtTheSmallerOne) {
  auto deck = read(std::string(kNodes) + "*EQUATION\n2\nBOTTOM, 1, 1., PAIR, 1, -1.\n" + kStep);
  const Diagnostic& d = deck->one(DiagCode::invalid_value);
  EXPECT_EQ(d.loc.line, 23u);
  EXPECT_EQ(d.loc.column, 16u);
  EXPECT_NE(d.message.find("node set 'PAIR' holds 2 nodes"), std::string::npos) << d.message;
  EXPECT_TRUE(deck->model.constraints.equations.empty());
}

TEST(Equations, ASingleFirstNodeCannotBeEliminatedPerSetEntry) {
  auto deck = read(std::string(kNodes) + "*EQUATION\n2\n9, 1, 1., TOP, 1, -1.\n" + kStep);
  const Diagnostic& d = deck->one(DiagCode::constraint_conflict);
  EXPECT_EQ(d.loc.line, 23u);
  EXPECT_EQ(d.loc.column, 1u);
  EXPECT_TRUE(deck->model.constraints.equations.empty());
}

TEST(Equations, FieldErrorsAreReportedAtTheirField) {
  expect_refusals({
      {"*EQUATION\n0\n", DiagCode::value_out_of_range, 22, 1},  // N < 1
      // N not an integer
      {"*EQUATION\n2.5\n1, 1, 1.\n", DiagCode::expected_integer, 22, 1},
      // zero first coefficient
      {"*EQUATION\n2\n1, 1, 0., 2, 1, 1.\n", DiagCode::value_out_of_range, 23, 7},
      {"*EQUATION\n2\n1, 7, 1., 2, 1, 1.\n", DiagCode::invalid_dof, 23, 4},  // DOF 7
      // more terms than N
      {"*EQUATION\n1\n1, 1, 1., 2, 1, 1.\n", DiagCode::too_many_fields, 23, 11},
      // fewer terms than N
      {"*EQUATION\n3\n1, 1, 1., 2, 1, 1.\n", DiagCode::missing_data_line, 22, 1},
      // no coefficient
      {"*EQUATION\n2\n1, 1, 1., 2, 1\n", DiagCode::missing_field, 23, 15},
      {"*EQUATION\n2\n1, 1, 1., 77, 1, 1.\n", DiagCode::undefined_node, 23, 11},
      {"*EQUATION\n2\n1, 1, 1., NOSET, 1, 1.\n", DiagCode::undefined_set, 23, 11},
      // DOF 1 of node 1 twice
      {"*EQUATION\n2\n1, 1, 1., 1, 1, -1.\n", DiagCode::invalid_value, 23, 14},
  });
}

TEST(Equations, RotationsAreRefusedUnderNlgeomAndOutOfPlaneDofsIn2D) {
  auto nlgeom = read(std::string(kNodes) + "*EQUATION\n2\n1, 1, 1., 2, 5, -1.\n" + kNlgeomStep);
  const Diagnostic& d = nlgeom->one(DiagCode::unsupported_option);
  EXPECT_EQ(d.loc.line, 23u);
  EXPECT_EQ(d.loc.column, 14u);
  // The same equation without NLGEOM is read.
  auto small = read(std::string(kNodes) + "*EQUATION\n2\n1, 1, 1., 2, 5, -1.\n" + kStep);
  EXPECT_TRUE(small->sink.diagnostics().empty()) << small->dump();
  EXPECT_EQ(small->model.constraints.equations.size(), 1u);

  auto planar = read(
      "*NODE\n1, 0, 0\n2, 1, 0\n*ELEMENT, TYPE=CONN2D2, ELSET=W\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=W\nCARTESIAN,\n*EQUATION\n2\n1, 6, 1., 2, 3, -1.\n" +
      std::string(kStep));
  const Diagnostic& p = planar->one(DiagCode::invalid_dof);
  EXPECT_EQ(p.loc.line, 10u);
  EXPECT_EQ(p.loc.column, 14u);
}

TEST(Equations, InstanceQualifiedNodesAndSets) {
  auto deck = read(
      "*PART, NAME=P\n*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n*NSET, NSET=S\n1, 2\n*END PART\n"
      "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=I1, PART=P\n*END INSTANCE\n"
      "*INSTANCE, NAME=I2, PART=P\n0, 0, 1\n*END INSTANCE\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=W\n1, I1.1, I2.1\n2, I1.2, I2.2\n"
      "*CONNECTOR SECTION, ELSET=W\nCARTESIAN,\n"
      "*EQUATION\n2\nI2.S, 3, 1., I1.S, 3, -1.\n*END ASSEMBLY\n" +
      std::string(kStep));
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const auto& c = deck->model.constraints;
  ASSERT_EQ(c.equations.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const Node& dependent =
        deck->model.nodes[static_cast<std::size_t>(c.equations[k].terms[0].node)];
    const Node& other = deck->model.nodes[static_cast<std::size_t>(c.equations[k].terms[1].node)];
    EXPECT_EQ(dependent.label, static_cast<std::int32_t>(k + 1));
    EXPECT_EQ(other.label, static_cast<std::int32_t>(k + 1));
    EXPECT_EQ(deck->model.instances[static_cast<std::size_t>(dependent.instance)].name.display,
              "I2");
    EXPECT_EQ(deck->model.instances[static_cast<std::size_t>(other.instance)].name.display, "I1");
  }
}

TEST(Equations, UnsortedSetsMatchedWithAnotherSetAreRefused) {
  // clinch keeps sets in ascending order, so the written order of an UNSORTED set is lost.
  auto deck = read(std::string(kNodes) +
                   "*NSET, NSET=BACK, UNSORTED\n8, 7, 6, 5\n"
                   "*EQUATION\n2\nBACK, 1, 1., BOTTOM, 1, -1.\n" +
                   kStep);
  const Diagnostic& d = deck->one(DiagCode::unsupported_option);
  EXPECT_EQ(d.loc.line, 25u);
  EXPECT_EQ(d.loc.column, 1u);
  EXPECT_TRUE(deck->model.constraints.equations.empty());
  // Against a single node its order does not matter.
  auto single = read(std::string(kNodes) +
                     "*NSET, NSET=BACK, UNSORTED\n8, 7, 6, 5\n"
                     "*MPC\nPIN, BACK, 9\n" +
                     kStep);
  EXPECT_TRUE(single->sink.diagnostics().empty()) << single->dump();
  EXPECT_EQ(single->model.constraints.followers.size(), 4u);
}

TEST(Equations, ALineMayEndWithAComma) {
  // CalculiX writes full lines of four terms with a trailing comma.
  auto deck = read(std::string(kNodes) +
                   "*EQUATION\n5\n1,1,1.,2,1,-.25,3,1,-.25,4,1,-.25,\n5,1,-.25\n" + kStep);
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const std::vector<std::vector<Term>> expected{
      {{1, 1, 1.0}, {2, 1, -0.25}, {3, 1, -0.25}, {4, 1, -0.25}, {5, 1, -0.25}}};
  EXPECT_EQ(equations(*deck), expected);
}

// ---- *MPC ------------------------------------------------------------------------------------

TEST(Mpcs, BeamTiePinAndLink) {
  auto deck =
      read(std::string(kNodes) + "*MPC\nBEAM, 5, 1\nTIE, 6, 2\npin, 7, 3\nLINK, 8, 4\n" + kStep);
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const std::map<std::int32_t, FollowerView> expected{
      {5, {1, 0x3F, true}}, {6, {2, 0x3F, false}}, {7, {3, 0x07, false}}};
  EXPECT_EQ(followers(*deck), expected);
  const auto& c = deck->model.constraints;
  ASSERT_EQ(c.links.size(), 1u);
  EXPECT_EQ(label(*deck, c.links[0].node), 8);
  EXPECT_EQ(label(*deck, c.links[0].other), 4);
  ASSERT_EQ(c.sources.size(), 4u);
  EXPECT_EQ(c.sources[0].keyword, "*MPC BEAM");
  EXPECT_EQ(c.sources[2].keyword, "*MPC PIN");
  EXPECT_EQ(c.sources[3].keyword, "*MPC LINK");
  EXPECT_EQ(c.sources[3].loc.line, 25u);
}

TEST(Mpcs, SetsArePairedAndASingleNodeSecondIsShared) {
  auto deck = read(std::string(kNodes) + "*MPC\nPIN, TOP, BOTTOM\nBEAM, PAIR, 9\n" + kStep);
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const std::map<std::int32_t, FollowerView> expected{{5, {1, 0x07, false}}, {6, {2, 0x07, false}},
                                                      {7, {3, 0x07, false}}, {8, {4, 0x07, false}},
                                                      {2, {9, 0x3F, true}},  {3, {9, 0x3F, true}}};
  EXPECT_EQ(followers(*deck), expected);
}

TEST(Mpcs, TwoDimensionalModelsUseDofsOneTwoSix) {
  auto deck = read(
      "*NODE\n1, 0, 0\n2, 1, 0\n3, 2, 0\n*ELEMENT, TYPE=CONN2D2, ELSET=W\n1, 1, 3\n"
      "*CONNECTOR SECTION, ELSET=W\nCARTESIAN,\n*MPC\nBEAM, 2, 1\nPIN, 3, 1\n" +
      std::string(kStep));
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const std::map<std::int32_t, FollowerView> expected{{2, {1, 0x23, true}}, {3, {1, 0x03, false}}};
  EXPECT_EQ(followers(*deck), expected);
}

TEST(Mpcs, RefusalsAtTheirField) {
  expect_refusals({
      {"*MPC\nREVOLUTE, 5, 1, 2\n", DiagCode::unsupported_option, 22, 1},
      {"*MPC\nSLIDER, 5, 1, 2\n", DiagCode::unsupported_option, 22, 1},
      {"*MPC, USER\n1, 5, 1\n", DiagCode::unsupported_option, 21, 7},
      {"*MPC\nBEAM, 5, 5\n", DiagCode::degenerate_mpc, 22, 1},
      {"*MPC\nBEAM, 5, TOP\n", DiagCode::invalid_value, 22, 10},
      {"*MPC\nTIE, TOP, PAIR\n", DiagCode::invalid_value, 22, 11},
      {"*MPC\nBEAM, 5\n", DiagCode::missing_field, 22, 8},
      {"*MPC\nBEAM, 5, 1, 2\n", DiagCode::too_many_fields, 22, 13},
      {"*NODE\n10, 0, 1, 0\n*MPC\nLINK, 10, 5\n", DiagCode::degenerate_mpc, 24, 1},
  });
}

// ---- Overconstraints -------------------------------------------------------------------------

TEST(Overconstraints, ADofTiedTwiceNamesBothLines) {
  auto deck =
      read(std::string(kNodes) + "*MPC\nPIN, 5, 1\n*EQUATION\n2\n5, 2, 1., 6, 2, -1.\n" + kStep);
  const Diagnostic& d = deck->one(DiagCode::constraint_conflict);
  EXPECT_EQ(d.loc.line, 25u);  // the later definition
  EXPECT_NE(d.message.find("DOF 2 of node 5 is tied twice"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("*MPC PIN at line 22"), std::string::npos) << d.message;
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].loc.line, 22u);
}

TEST(Overconstraints, ARigidBodyNodeTiedByAnMpc) {
  auto deck = read(std::string(kNodes) +
                   "*NSET, NSET=BODY\n5, 6\n*RIGID BODY, REF NODE=1, TIE NSET=BODY\n"
                   "*MPC\nBEAM, 6, 2\n" +
                   kStep);
  const Diagnostic& d = deck->one(DiagCode::constraint_conflict);
  EXPECT_EQ(d.loc.line, 25u);
  EXPECT_NE(d.message.find("*RIGID BODY at line 23"), std::string::npos) << d.message;
}

TEST(Overconstraints, APrescribedDependentDofPointsToTheReferenceNode) {
  auto deck = read(std::string(kNodes) +
                   "*MPC\nBEAM, 5, 1\n*BOUNDARY\n9, 1, 6\n*STEP\n*STATIC\n"
                   "*BOUNDARY\n5, 2, 2, 0.1\n*END STEP\n");
  const Diagnostic& d = deck->one(DiagCode::dependent_dof_prescribed);
  EXPECT_EQ(d.loc.line, 28u);
  EXPECT_NE(d.message.find("DOF 2 of node 5"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("*MPC BEAM at line 22"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("node 1"), std::string::npos) << d.message;
}

TEST(Overconstraints, ChainsAreSubstitutedButCyclesAreErrors) {
  // 5 follows 1, 1 follows 2: a chain, accepted without NLGEOM.
  auto chain = read(std::string(kNodes) + "*MPC\nBEAM, 5, 1\nBEAM, 1, 2\n" + kStep);
  EXPECT_TRUE(chain->sink.diagnostics().empty()) << chain->dump();
  // u1(5) = u1(6), u1(6) = u1(5): a cycle.
  auto cycle = read(std::string(kNodes) +
                    "*EQUATION\n2\n5, 1, 1., 6, 1, -1.\n2\n"
                    "6, 1, 1., 5, 1, -1.\n" +
                    kStep);
  const Diagnostic& d = cycle->one(DiagCode::constraint_cycle);
  EXPECT_EQ(d.loc.line, 25u);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].loc.line, 23u);
}

TEST(Overconstraints, NonlinearChainsUnderNlgeom) {
  // The BEAM has an arm (nodes 5 and 1 are one unit apart) and its reference node follows node
  // 2 by a TIE: refused under NLGEOM, accepted without.
  const std::string mpcs = std::string(kNodes) + "*MPC\nBEAM, 5, 1\nTIE, 1, 2\n";
  auto nlgeom = read(mpcs + kNlgeomStep);
  const Diagnostic& d = nlgeom->one(DiagCode::constraint_not_under_nlgeom);
  EXPECT_EQ(d.loc.line, 23u);
  EXPECT_NE(d.message.find("*MPC BEAM at line 22"), std::string::npos) << d.message;
  EXPECT_TRUE(read(mpcs + kStep)->sink.diagnostics().empty());
  // Chains of TIEs (no arm) stay exact under NLGEOM.
  auto ties = read(std::string(kNodes) + "*MPC\nTIE, 5, 1\nTIE, 1, 2\n" + kNlgeomStep);
  EXPECT_TRUE(ties->sink.diagnostics().empty()) << ties->dump();
}

TEST(Overconstraints, LinearisedAndPartialRotationCouplingsUnderNlgeom) {
  auto distributing = read(std::string(kNodes) +
                           "*SURFACE, TYPE=NODE, NAME=S\nTOP\nBOTTOM\n"
                           "*COUPLING, REF NODE=9, SURFACE=S, CONSTRAINT NAME=C\n*DISTRIBUTING\n" +
                           kNlgeomStep);
  const Diagnostic& d = distributing->one(DiagCode::constraint_not_under_nlgeom);
  EXPECT_EQ(d.loc.line, 24u);
  EXPECT_NE(d.message.find("linearised"), std::string::npos) << d.message;

  auto partial =
      read(std::string(kNodes) + "*KINEMATIC COUPLING, REF NODE=9\n5, 1, 4\n" + kNlgeomStep);
  const Diagnostic& p = partial->one(DiagCode::constraint_not_under_nlgeom);
  EXPECT_EQ(p.loc.line, 21u);
  EXPECT_NE(p.message.find("some but not all rotations"), std::string::npos) << p.message;
  // The same couplings without NLGEOM are accepted.
  EXPECT_TRUE(read(std::string(kNodes) + "*KINEMATIC COUPLING, REF NODE=9\n5, 1, 4\n" + kStep)
                  ->sink.diagnostics()
                  .empty());
}

TEST(Overconstraints, AConnectorInsideARigidGroupWithConstrainedComponents) {
  // Nodes 5 and 6 both follow node 1 rigidly; a JOIN between them constrains components 1-3
  // that the body already fixes. A CARTESIAN (no constrained component) between them is fine.
  const std::string body = std::string(kNodes) + "*MPC\nBEAM, 5, 1\nBEAM, 6, 1\n";
  auto join = read(body +
                   "*ELEMENT, TYPE=CONN3D2, ELSET=J\n101, 5, 6\n"
                   "*CONNECTOR SECTION, ELSET=J\nJOIN,\n" +
                   kStep);
  const Diagnostic& d = join->one(DiagCode::connector_overconstraint);
  EXPECT_EQ(d.loc.line, 25u);
  EXPECT_NE(d.message.find("components 1, 2, 3"), std::string::npos) << d.message;
  auto cartesian = read(body +
                        "*ELEMENT, TYPE=CONN3D2, ELSET=J\n101, 5, 6\n"
                        "*CONNECTOR SECTION, ELSET=J\nCARTESIAN,\n" +
                        kStep);
  EXPECT_TRUE(cartesian->with(DiagCode::connector_overconstraint).empty()) << cartesian->dump();
  // RIGID elasticity on a free component counts as constrained; the reference node itself as
  // one end.
  auto rigid = read(body +
                    "*ELEMENT, TYPE=CONN3D2, ELSET=J\n101, 1, 6\n"
                    "*CONNECTOR SECTION, ELSET=J, BEHAVIOR=B\nCARTESIAN,\n"
                    "*CONNECTOR BEHAVIOR, NAME=B\n*CONNECTOR ELASTICITY, RIGID\n2\n" +
                    kStep);
  const Diagnostic& r = rigid->one(DiagCode::connector_overconstraint);
  EXPECT_NE(r.message.find("component 2 "), std::string::npos) << r.message;
}

}  // namespace
}  // namespace clinch
