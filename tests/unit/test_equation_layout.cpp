// Vectors by rows (docs/parallel.md): a rank's plan over its own equations, the rows it owns and
// the ghosts its elements read. Over the ranks the owned rows are every equation once, each
// record's local equations stand for the whole plan's, and the rank parts of the tangent, mapped
// to the global equations, sum to the serial tangent.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <set>

#include "parser/deck_reader.hpp"
#include "src/assembly/analysis_plan.hpp"
#include "src/assembly/assembly_pattern.hpp"
#include "src/assembly/connector_system.hpp"
#include "tests/unit/checked_deck.hpp"
#include "tests/unit/part_communicator.hpp"

namespace clinch {
namespace {

// A strip of eight nodes in two rows, springs along and across it, an elastic AXIAL connector
// across each square, each node tied to the ground by a SPRING1 on DOF 3; node 1 and 5 held. No
// multipliers: the plan's vectors may run by rows.
std::string strip_deck() {
  std::string deck = "*NODE\n";
  for (int k = 0; k < 4; ++k) {
    deck += std::to_string(k + 1) + ", " + std::to_string(k) + ".0, 0., 0.\n";
    deck += std::to_string(k + 5) + ", " + std::to_string(k) + ".0, 1., 0.\n";
  }
  deck +=
      "*ELEMENT, TYPE=SPRINGA, ELSET=A\n1, 1, 2\n2, 2, 3\n3, 3, 4\n4, 5, 6\n5, 6, 7\n6, 7, 8\n"
      "7, 1, 5\n8, 2, 6\n9, 3, 7\n10, 4, 8\n"
      "*SPRING, ELSET=A\n\n100.\n"
      "*ELEMENT, TYPE=SPRING1, ELSET=Z\n11, 1\n12, 2\n13, 3\n14, 4\n15, 5\n16, 6\n17, 7\n18, 8\n"
      "*SPRING, ELSET=Z\n3\n10.\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=C\n21, 1, 6\n22, 2, 7\n23, 3, 8\n"
      "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=AX\nAXIAL,\n"
      "*CONNECTOR BEHAVIOR, NAME=AX\n*CONNECTOR ELASTICITY, COMPONENT=1\n50.\n"
      "*BOUNDARY\n1, 1, 3\n5, 1, 3\n*STEP, NLGEOM\n*STATIC\n*CLOAD\n4, 1, 1.\n*END STEP\n";
  return deck;
}

// A deck read and checked, with the plan of the whole model and those of the ranks.
struct PlannedDeck {
  CheckedDeck deck;
  std::optional<AnalysisPlan> whole;
  explicit PlannedDeck(const std::string& text) {
    read_deck_text("deck.inp", text, deck.sources, deck.model, deck.sink);
    EXPECT_FALSE(deck.sink.has_errors()) << deck.dump();
    std::string error;
    whole = build_analysis_plan(deck.model, &error);
    EXPECT_TRUE(whole) << error;
  }
  std::optional<AnalysisPlan> rank_plan(int rank, int ranks) const {
    const PlanShare share{rank, ranks, true};
    std::string error;
    std::optional<AnalysisPlan> plan = build_analysis_plan(deck.model, &error, &share);
    EXPECT_TRUE(plan) << error;
    return plan;
  }
};

TEST(EquationLayout, TheRanksOwnEveryEquationOnceAndTheirRecordsStandForTheWholePlans) {
  const PlannedDeck strip(strip_deck());
  ASSERT_TRUE(strip.whole);
  const int n = strip.whole->dofs.equations();
  ASSERT_EQ(n, 24);
  constexpr int kRanks = 3;
  int next = 0;
  std::size_t ghosts = 0;
  for (int rank = 0; rank < kRanks; ++rank) {
    const std::optional<AnalysisPlan> plan = strip.rank_plan(rank, kRanks);
    ASSERT_TRUE(plan);
    const EquationLayout& layout = plan->layout;
    ASSERT_TRUE(layout.local);
    EXPECT_EQ(layout.global_count, n);
    EXPECT_EQ(layout.node_block, 3);
    // Consecutive owned rows, on node boundaries.
    EXPECT_EQ(layout.first_owned, next);
    EXPECT_EQ(layout.owned % 3, 0);
    next += layout.owned;
    EXPECT_EQ(plan->dofs.equations(), layout.owned + static_cast<int>(layout.ghost_global.size()));
    EXPECT_TRUE(std::is_sorted(layout.ghost_global.begin(), layout.ghost_global.end()));
    for (int local = 0; local < plan->dofs.equations(); ++local) {
      const int global = layout.global_of(local);
      EXPECT_EQ(layout.local_of(global), local);
      EXPECT_EQ(layout.owns(local),
                global >= layout.first_owned && global < layout.first_owned + layout.owned);
      // The same node and DOF in both numberings.
      const std::int32_t node = plan->dofs.node_of(local);
      EXPECT_EQ(strip.whole->dofs.equation(node, plan->dofs.dof_of(local)), global);
    }
    // The records' local equations are the whole plan's, renumbered.
    const auto same_equations = [&](const LocalEquations& mine, const LocalEquations& theirs) {
      ASSERT_EQ(mine.count, theirs.count);
      for (std::size_t k = 0; k < static_cast<std::size_t>(mine.count); ++k) {
        EXPECT_EQ(layout.global_of(mine.equation[k]), theirs.equation[k]);
      }
    };
    for (std::size_t s = 0; s < plan->springs.size(); ++s) {
      same_equations(plan->springs[s].local, strip.whole->springs[plan->first_spring + s].local);
    }
    for (std::size_t c = 0; c < plan->connectors.size(); ++c) {
      same_equations(plan->connectors[c].local,
                     strip.whole->connectors[plan->first_connector + c].local);
    }
    ghosts += layout.ghost_global.size();
  }
  EXPECT_EQ(next, n);
  EXPECT_GT(ghosts, 0u);
}

// A JOIN's three multipliers are rows of the rank that holds the connector, after its nodes'
// equations; the solver's numbering gives each rank consecutive rows.
TEST(EquationLayout, MultipliersAreRowsOfTheirConnectorsRank) {
  const PlannedDeck join(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 0., 0.\n"
      "*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 2, 3\n*SPRING, ELSET=S\n\n10.\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=C\n2, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C\nJOIN,\n*BOUNDARY\n1, 1, 3\n*STEP\n*STATIC\n"
      "*CLOAD\n3, 1, 1.\n*END STEP\n");
  int next = 0;
  for (int rank = 0; rank < 2; ++rank) {
    const std::optional<AnalysisPlan> plan = join.rank_plan(rank, 2);
    ASSERT_TRUE(plan);
    const EquationLayout& layout = plan->layout;
    ASSERT_TRUE(layout.local);
    EXPECT_EQ(layout.global_count, 12);  // nine nodal equations and three multipliers
    EXPECT_EQ(layout.first_owned, next);
    next += layout.owned;
    // Rank 0 holds the JOIN (one connector over two ranks: shares of one and none) and owns
    // nodes 1 and 2 (the node equations split 6 and 3): six nodal rows, then the multipliers.
    const int multipliers = rank == 0 ? 3 : 0;
    EXPECT_EQ(layout.owned, (rank == 0 ? 6 : 3) + multipliers) << rank;
    for (int k = 0; k < multipliers; ++k) {
      EXPECT_LT(plan->dofs.node_of(6 + k), 0);
      EXPECT_EQ(plan->dofs.field(6 + k), EquationField::TranslationalMultiplier);
    }
    if (rank == 0) {
      const ConnectorRecord& join = plan->connectors.at(0);
      EXPECT_EQ(join.multiplier_count, 3);
      EXPECT_EQ(join.local.equation[static_cast<std::size_t>(join.column_count)], 6);
    }
    // Each rank's ghosts: rank 0's spring reads node 3 of rank 1; rank 1 holds no element.
    EXPECT_EQ(layout.ghost_global.size(), rank == 0 ? 3u : 0u);
    if (rank == 0) EXPECT_EQ(layout.ghost_global.front(), 9);
  }
  EXPECT_EQ(next, 12);
}

// The strip with a rigid body: nodes 3, 4 and 8 follow reference node 9, and an *EQUATION ties u2
// of node 6 to that of node 2. Three equal shares of the node equations would give the body's
// nodes to ranks 1 and 2; each constraint lies on one rank with its reference node.
std::string constrained_strip_deck() {
  std::string deck = strip_deck();
  const std::string reference =
      "9, 2.5, 0.5, 0.\n*NSET, NSET=BODY\n3, 4, 8\n*RIGID BODY, REF NODE=9, TIE NSET=BODY\n"
      "*EQUATION\n2\n6, 2, 1., 2, 2, -1.\n";
  deck.insert(deck.find("*ELEMENT"), reference);
  // Small displacements (see RankPartsWithKinematicConstraintsSumToTheSerialTangent).
  deck.replace(deck.find("*STEP, NLGEOM"), 13, "*STEP");
  const std::string load = "*CLOAD\n4, 1, 1.";
  deck.replace(deck.find(load), load.size(), "*CLOAD\n9, 6, 0.3\n4, 1, 1.");
  return deck;
}

// Newton's unknown `solved` of `plan` as the whole plan's: by node and DOF.
int whole_unknown(const AnalysisPlan& plan, const AnalysisPlan& whole, int solved) {
  const int eq = plan.dependents.equation(solved);
  const std::int32_t node = plan.dofs.node_of(eq);
  return whole.dependents.solved(whole.dofs.equation(node, plan.dofs.dof_of(eq)));
}

TEST(EquationLayout, EachConstraintLiesOnOneRankAndItsMapsReadHeldEquations) {
  const PlannedDeck strip(constrained_strip_deck());
  ASSERT_TRUE(strip.whole);
  const AnalysisPlan& whole = *strip.whole;
  // Nodes 3, 4, 8 (translations) and u2 of node 6 follow.
  ASSERT_EQ(whole.dependents.dofs.size(), 10u);
  constexpr int kRanks = 3;
  std::set<int> owners_of_body, owners_of_equation;
  int next = 0, next_solved = 0;
  for (int rank = 0; rank < kRanks; ++rank) {
    const std::optional<AnalysisPlan> plan = strip.rank_plan(rank, kRanks);
    ASSERT_TRUE(plan);
    const EquationLayout& layout = plan->layout;
    const EquationLayout& solved = plan->solved_layout;
    ASSERT_TRUE(layout.local && solved.local);
    EXPECT_EQ(layout.global_count, whole.dofs.equations());
    EXPECT_EQ(solved.global_count, whole.dependents.solved_count(whole.dofs));
    EXPECT_EQ(layout.first_owned, next);
    EXPECT_EQ(solved.first_owned, next_solved);
    next += layout.owned;
    next_solved += solved.owned;
    EXPECT_TRUE(std::is_sorted(solved.ghost_global.begin(), solved.ghost_global.end()));
    EXPECT_EQ(plan->dependents.solved_count(plan->dofs),
              solved.owned + static_cast<int>(solved.ghost_global.size()));
    const auto owns_node = [&](std::int32_t label) {
      const auto& nodes = strip.deck.model.nodes;
      const auto node =
          std::find_if(nodes.begin(), nodes.end(), [&](const Node& n) { return n.label == label; });
      const int eq = plan->dofs.equation(static_cast<std::int32_t>(node - nodes.begin()), 1);
      return eq >= 0 && layout.owns(eq);
    };
    for (const std::int32_t label : {3, 4, 8, 9}) {
      if (owns_node(label)) owners_of_body.insert(rank);
    }
    for (const std::int32_t label : {2, 6}) {
      if (owns_node(label)) owners_of_equation.insert(rank);
    }
    // Each dependent DOF held is the whole plan's, reading the same equations.
    for (const DependentDof& d : plan->dependents.dofs) {
      const int eq = whole.dofs.equation(d.node, plan->dofs.dof_of(d.equation));
      ASSERT_TRUE(whole.dependents.is_dependent(eq));
      const DependentDof& w = whole.dependents.dofs[static_cast<std::size_t>(
          whole.dependents.of_equation[static_cast<std::size_t>(eq)])];
      ASSERT_EQ(d.term_count, w.term_count);
      ASSERT_EQ(d.resolved_count, w.resolved_count);
      const auto same = [&](int mine, int theirs) {
        if (theirs < 0) return mine < 0;
        return mine >= 0 &&
               whole.dofs.equation(plan->dofs.node_of(mine), plan->dofs.dof_of(mine)) == theirs;
      };
      for (std::uint32_t t = 0; t < d.term_count; ++t) {
        EXPECT_TRUE(same(plan->dependents.term_equation[d.first_term + t],
                         whole.dependents.term_equation[w.first_term + t]));
      }
      for (std::uint32_t e = 0; e < d.resolved_count; ++e) {
        EXPECT_TRUE(same(plan->dependents.resolved_equation[d.first_resolved + e],
                         whole.dependents.resolved_equation[w.first_resolved + e]));
      }
    }
  }
  EXPECT_EQ(next, whole.dofs.equations());
  EXPECT_EQ(next_solved, whole.dependents.solved_count(whole.dofs));
  EXPECT_EQ(owners_of_body.size(), 1u);
  EXPECT_EQ(owners_of_equation.size(), 1u);
}

// A STABILIZE step runs by rows too: each rank's plan is over its own equations and its ghosts.
TEST(EquationLayout, AStabilizedStepRunsByRows) {
  const PlannedDeck stabilized(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 1, 2\n"
      "*SPRING, ELSET=S\n\n10.\n*BOUNDARY\n1, 1, 3\n*STEP\n*STATIC, STABILIZE\n0.1, 1.\n"
      "*CLOAD\n2, 1, 1.\n*END STEP\n");
  for (int rank = 0; rank < 2; ++rank) {
    const std::optional<AnalysisPlan> plan = stabilized.rank_plan(rank, 2);
    ASSERT_TRUE(plan);
    EXPECT_TRUE(plan->stabilized);
    EXPECT_TRUE(plan->layout.local);
    // The spring's rank holds both nodes; the other owns node 2 and holds nothing else.
    EXPECT_EQ(plan->dofs.equations(), rank == 0 ? 6 : 3);
  }
}

// A dynamic step: each rank holds the inertia of the nodes it holds, its own first, over its
// local equations.
TEST(EquationLayout, TheInertiaOfTheNodesARankHoldsItsOwnFirst) {
  const PlannedDeck dynamic(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 0., 0.\n"
      "*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 1, 2\n2, 2, 3\n"
      "*SPRING, ELSET=S\n\n10.\n*ELEMENT, TYPE=MASS, ELSET=M\n3, 2\n4, 3\n"
      "*MASS, ELSET=M\n1.\n*BOUNDARY\n1, 1, 3\n*STEP\n*DYNAMIC\n0.1, 1.\n"
      "*CLOAD\n3, 1, 1.\n*END STEP\n");
  ASSERT_TRUE(dynamic.whole);
  EXPECT_EQ(dynamic.whole->inertia.size(), 2u);
  std::size_t owned = 0;
  for (int rank = 0; rank < 2; ++rank) {
    const std::optional<AnalysisPlan> plan = dynamic.rank_plan(rank, 2);
    ASSERT_TRUE(plan);
    ASSERT_TRUE(plan->layout.local);
    for (std::size_t k = 0; k < plan->inertia.size(); ++k) {
      const NodeInertia& n = plan->inertia[k];
      const int eq = n.translation[0];
      ASSERT_GE(eq, 0);
      EXPECT_EQ(plan->dofs.node_of(eq), n.node);
      EXPECT_EQ(plan->layout.owns(eq), k < plan->owned_inertia);
    }
    owned += plan->own_inertia().size();
  }
  EXPECT_EQ(owned, 2u);
}

// The matrix `m` stands for, dense, over the whole plan's unknowns (`unknown` of its rows).
template <typename Unknown>
Eigen::MatrixXd dense_whole(const SparseMatrix& m, int n, Unknown unknown) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < m.n; ++j) {
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
      const int i = m.row_idx[p];
      out(unknown(i), unknown(j)) += m.values[p];
      if (m.symmetric_upper && i != j) out(unknown(j), unknown(i)) += m.values[p];
    }
  }
  return out;
}

// The rank parts of the tangent over their local unknowns, taken to the whole plan's, sum to the
// serial tangent.
void expect_rank_parts_sum_to_the_serial_tangent(const PlannedDeck& deck, bool nlgeom) {
  ASSERT_TRUE(deck.whole);
  const AnalysisPlan& whole = *deck.whole;
  const int n = whole.dependents.solved_count(whole.dofs);
  // The same state for every system, away from the initial one (NLGEOM turns the springs), and
  // nodes 1 and 5 held: their rows are the identity, which only their owner adds.
  Eigen::VectorXd dx(n);
  for (int i = 0; i < n; ++i) dx[i] = 0.01 * std::sin(1.7 * i + 0.3);
  const auto prepare = [&](ConnectorSystem& system, const AnalysisPlan& plan) {
    for (const std::int32_t node : {0, 4}) {
      for (int dof = 1; dof <= 3; ++dof) {
        if (const int eq = plan.dofs.equation(node, dof); eq >= 0) {
          system.conditions().prescribe(eq, 0.0);
        }
      }
    }
    system.set_nlgeom(nlgeom);
    Eigen::VectorXd mine(system.size());
    for (int i = 0; i < mine.size(); ++i) mine[i] = dx[whole_unknown(plan, whole, i)];
    system.apply_correction(mine);
  };
  ConnectorSystem serial(deck.deck.model, whole);
  prepare(serial, whole);
  SparseMatrix k = serial.pattern();
  Eigen::VectorXd r(serial.size());
  const EvalStatus serial_status = serial.evaluate(r, &k);
  ASSERT_TRUE(serial_status.ok) << serial_status.message;
  const Eigen::MatrixXd expected = dense_whole(k, n, [](int i) { return i; });
  constexpr int kRanks = 3;
  Eigen::MatrixXd summed = Eigen::MatrixXd::Zero(n, n);
  for (int rank = 0; rank < kRanks; ++rank) {
    const std::optional<AnalysisPlan> plan = deck.rank_plan(rank, kRanks);
    ASSERT_TRUE(plan);
    PartCommunicator communicator(rank, kRanks);
    ConnectorSystem part(deck.deck.model, *plan);
    part.distribute(communicator, true);
    prepare(part, *plan);
    SparseMatrix k_part = part.pattern();
    ASSERT_TRUE(k_part.partial());
    EXPECT_EQ(k_part.summed_size(), n);
    EXPECT_EQ(k_part.global_first_row, plan->solved_layout.first_owned);
    Eigen::VectorXd r_part(part.size());
    const EvalStatus status = part.evaluate(r_part, &k_part);
    ASSERT_TRUE(status.ok) << status.message;
    summed += dense_whole(k_part, n, [&](int i) { return whole_unknown(*plan, whole, i); });
  }
  // Sums of the same element terms in another order: round-off of the largest entry.
  EXPECT_LE((summed - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 0.0);
}

TEST(EquationLayout, RankPartsOverLocalEquationsSumToTheSerialTangent) {
  expect_rank_parts_sum_to_the_serial_tangent(PlannedDeck(strip_deck()), true);
}

// Elements condensed onto the reference node and the equation's other node from three ranks.
// Small displacements: the curvature of the rigid arms under NLGEOM takes the force on the tie
// nodes summed over the ranks, which the parts of this test do not exchange (the mpi_ cases
// with rigid bodies under NLGEOM run it against the serial run).
TEST(EquationLayout, RankPartsWithKinematicConstraintsSumToTheSerialTangent) {
  expect_rank_parts_sum_to_the_serial_tangent(PlannedDeck(constrained_strip_deck()), false);
}

}  // namespace
}  // namespace clinch
