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
  EXPECT_EQ(whole_vectors_need(*strip.whole), "");
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
    EXPECT_EQ(whole_vectors_need(*plan), "");
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

TEST(EquationLayout, WholeVectorsWhereAFeatureNeedsThem) {
  const PlannedDeck dynamic(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 1, 2\n"
      "*SPRING, ELSET=S\n\n10.\n*ELEMENT, TYPE=MASS, ELSET=M\n2, 2\n"
      "*MASS, ELSET=M\n1.\n*BOUNDARY\n1, 1, 3\n*STEP\n*DYNAMIC\n0.1, 1.\n"
      "*CLOAD\n2, 1, 1.\n*END STEP\n");
  const std::optional<AnalysisPlan> plan = dynamic.rank_plan(0, 2);
  ASSERT_TRUE(plan);
  EXPECT_EQ(whole_vectors_need(*plan), "a dynamic or *FREQUENCY step");
  EXPECT_FALSE(plan->layout.local);
  EXPECT_EQ(plan->dofs.equations(), 6);
}

// The matrix `m` stands for, dense, over the global equations.
Eigen::MatrixXd dense_global(const SparseMatrix& m, int n) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
  const auto global = [&](int i) {
    return m.global_equation.empty() ? i : m.global_equation[static_cast<std::size_t>(i)];
  };
  for (int j = 0; j < m.n; ++j) {
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
      const int i = m.row_idx[p];
      out(global(i), global(j)) += m.values[p];
      if (m.symmetric_upper && i != j) out(global(j), global(i)) += m.values[p];
    }
  }
  return out;
}

TEST(EquationLayout, RankPartsOverLocalEquationsSumToTheSerialTangent) {
  const PlannedDeck strip(strip_deck());
  ASSERT_TRUE(strip.whole);
  const AnalysisPlan& whole = *strip.whole;
  const int n = whole.dofs.equations();
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
    system.set_nlgeom(true);
    Eigen::VectorXd mine(system.size());
    for (int i = 0; i < mine.size(); ++i) mine[i] = dx[plan.layout.global_of(i)];
    system.apply_correction(mine);
  };
  ConnectorSystem serial(strip.deck.model, whole);
  prepare(serial, whole);
  SparseMatrix k = serial.pattern();
  Eigen::VectorXd r(serial.size());
  ASSERT_TRUE(serial.evaluate(r, &k).ok);
  const Eigen::MatrixXd expected = dense_global(k, n);
  constexpr int kRanks = 3;
  Eigen::MatrixXd summed = Eigen::MatrixXd::Zero(n, n);
  for (int rank = 0; rank < kRanks; ++rank) {
    const std::optional<AnalysisPlan> plan = strip.rank_plan(rank, kRanks);
    ASSERT_TRUE(plan);
    PartCommunicator communicator(rank, kRanks);
    ConnectorSystem part(strip.deck.model, *plan);
    part.distribute(communicator, true);
    prepare(part, *plan);
    SparseMatrix k_part = part.pattern();
    ASSERT_TRUE(k_part.partial());
    EXPECT_EQ(k_part.summed_size(), n);
    EXPECT_EQ(k_part.global_first_row, plan->layout.first_owned);
    Eigen::VectorXd r_part(part.size());
    ASSERT_TRUE(part.evaluate(r_part, &k_part).ok);
    summed += dense_global(k_part, n);
  }
  // Sums of the same element terms in another order: round-off of the largest entry.
  EXPECT_LE((summed - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace clinch
