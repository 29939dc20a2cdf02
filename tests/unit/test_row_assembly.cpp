// Assembly by rows (docs/parallel.md): a rank's plan holds its share of the connectors and
// springs, and its pattern the entries of those elements and the diagonals of the rows it owns.
// Over the ranks the shares are the whole plan and the parts cover the whole pattern, entry for
// entry.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdlib>
#include <set>
#include <utility>

#include "parser/deck_reader.hpp"
#include "src/assembly/analysis_plan.hpp"
#include "src/assembly/assembly_pattern.hpp"
#include "src/assembly/connector_system.hpp"
#include "src/assembly/sparsity_pattern.hpp"
#include "tests/unit/checked_deck.hpp"
#include "tests/unit/part_communicator.hpp"

namespace clinch {
namespace {

using Entries = std::set<std::pair<int, int>>;  // (row, column) as stored

Entries entries_of(const SparseMatrix& m) {
  Entries out;
  for (int j = 0; j < m.n; ++j) {
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) out.emplace(m.row_idx[p], j);
  }
  return out;
}

TEST(SparsityBuilder, PresetDiagonalsOnlyForTheGivenRowsAndForCoupledEquations) {
  SparsityBuilder builder(4, true, 1, 2);
  const int coupled[] = {0, 3};
  builder.couple(coupled);
  const SparseMatrix m = builder.build();
  validate_pattern(m);
  EXPECT_EQ(entries_of(m), (Entries{{0, 0}, {1, 1}, {0, 3}, {3, 3}}));
}

// Eight SPRINGA elements around and across a square of four free nodes, each also tied to the
// ground node 5 by a SPRING1 on DOF 3; three connectors across it: an elastic AXIAL, a
// CARTESIAN with a stop on component 1 and a JOIN (multipliers of its own).
std::string square_deck() {
  return "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n5, 2., 2., 0.\n"
         "*ELEMENT, TYPE=SPRINGA, ELSET=A\n1, 1, 2\n2, 2, 3\n3, 3, 4\n4, 4, 1\n5, 1, 3\n6, 2, 4\n"
         "7, 1, 5\n8, 3, 5\n"
         "*SPRING, ELSET=A\n\n100.\n"
         "*ELEMENT, TYPE=SPRING1, ELSET=Z\n11, 1\n12, 2\n13, 3\n14, 4\n"
         "*SPRING, ELSET=Z\n3\n10.\n"
         "*ELEMENT, TYPE=CONN3D2, ELSET=CA\n21, 1, 3\n"
         "*ELEMENT, TYPE=CONN3D2, ELSET=CC\n22, 2, 4\n"
         "*ELEMENT, TYPE=CONN3D2, ELSET=CJ\n23, 4, 5\n"
         "*CONNECTOR SECTION, ELSET=CA, BEHAVIOR=AX\nAXIAL,\n"
         "*CONNECTOR SECTION, ELSET=CC, BEHAVIOR=CT\nCARTESIAN,\n"
         "*CONNECTOR SECTION, ELSET=CJ\nJOIN,\n"
         "*CONNECTOR BEHAVIOR, NAME=AX\n*CONNECTOR ELASTICITY, COMPONENT=1\n50.\n"
         "*CONNECTOR BEHAVIOR, NAME=CT\n*CONNECTOR ELASTICITY, COMPONENT=1\n20.\n"
         "*CONNECTOR ELASTICITY, COMPONENT=2\n30.\n*CONNECTOR ELASTICITY, COMPONENT=3\n40.\n"
         "*CONNECTOR STOP, COMPONENT=1\n-2., 2.\n"
         "*BOUNDARY\n5, 1, 3\n*STEP\n*STATIC\n*CLOAD\n3, 1, 1.\n*END STEP\n";
}

// The square deck, read and checked, with the plan of the whole model.
struct Square {
  CheckedDeck deck;
  std::optional<AnalysisPlan> whole;
  Square() {
    read_deck_text("square.inp", square_deck(), deck.sources, deck.model, deck.sink);
    EXPECT_FALSE(deck.sink.has_errors()) << deck.dump();
    std::string error;
    whole = build_analysis_plan(deck.model, &error);
    EXPECT_TRUE(whole) << error;
  }
};

TEST(RowAssembly, RankSharesOfTheElementsAndPatternPartsMakeTheWhole) {
  const Square square;
  ASSERT_TRUE(square.whole);
  const CheckedDeck& deck = square.deck;
  const std::optional<AnalysisPlan>& whole = square.whole;
  std::string error;
  ASSERT_EQ(whole->spring_total, 12u);
  ASSERT_FALSE(whole->shared);
  const AssemblyPattern whole_pattern = build_assembly_pattern(*whole, true);
  const int n = whole_pattern.matrix.n;
  constexpr int kRanks = 3;
  std::vector<std::int32_t> elements;
  Entries covered;
  int next_row = 0;
  std::size_t history = 0;
  for (int rank = 0; rank < kRanks; ++rank) {
    const PlanShare share{rank, kRanks};
    const std::optional<AnalysisPlan> plan = build_analysis_plan(deck.model, &error, &share);
    ASSERT_TRUE(plan) << error;
    EXPECT_EQ(plan->spring_total, whole->spring_total);
    EXPECT_EQ(plan->springs.size(), 4u);  // 12 springs over 3 ranks
    EXPECT_TRUE(plan->shared);
    for (const SpringRecord& s : plan->springs) elements.push_back(s.element);
    const ItemRange springs{plan->first_spring, plan->first_spring + plan->springs.size()};
    const RowAssemblyShare rows{{0, plan->connectors.size()}, springs, rank, kRanks};
    const AssemblyPattern part = build_assembly_pattern(*plan, true, &rows);
    validate_pattern(part.matrix);
    ASSERT_TRUE(part.matrix.partial());
    // The ranks own consecutive rows (with multipliers in the system, in blocks of one row:
    // DofMap::uniform_node_block).
    EXPECT_EQ(part.matrix.first_owned_row, next_row);
    next_row += part.matrix.owned_rows;
    for (int i = 0; i < n; ++i) {
      if (part.matrix.owns_row(i)) {
        EXPECT_GE(part.diagonal[static_cast<std::size_t>(i)], 0) << i;
      }
    }
    const Entries mine = entries_of(part.matrix);
    for (const auto& entry : mine) EXPECT_TRUE(entries_of(whole_pattern.matrix).count(entry));
    covered.insert(mine.begin(), mine.end());
    // Each spring's positions are in its rank's part.
    EXPECT_EQ(part.spring_offset.size(), plan->springs.size());
    // One connector each; the multipliers numbered as in the whole plan, and the whole model's
    // decisions (symmetric laws, multipliers) the same on every rank.
    ASSERT_EQ(plan->connectors.size(), 1u);
    EXPECT_EQ(plan->connector_total, 3u);
    EXPECT_EQ(plan->first_connector, static_cast<std::size_t>(rank));
    const ConnectorRecord& mine_record = plan->connectors[0];
    const ConnectorRecord& whole_record = whole->connectors[static_cast<std::size_t>(rank)];
    EXPECT_EQ(mine_record.element, whole_record.element);
    EXPECT_EQ(mine_record.local.equation, whole_record.local.equation);
    EXPECT_EQ(mine_record.laws.count, whole_record.laws.count);
    EXPECT_EQ(plan->dofs.equations(), whole->dofs.equations());
    EXPECT_EQ(plan->laws_symmetric(), whole->laws_symmetric());
    EXPECT_EQ(plan->has_multipliers, whole->has_multipliers);
    EXPECT_EQ(plan->connector_of_element, whole->connector_of_element);
    history += plan->history_size;
    EXPECT_EQ(part.connector_offset.size(), 1u);
  }
  EXPECT_EQ(next_row, n);
  EXPECT_EQ(covered, entries_of(whole_pattern.matrix));
  EXPECT_EQ(history, whole->history_size);
  std::vector<std::int32_t> all;
  for (const SpringRecord& s : whole->springs) all.push_back(s.element);
  EXPECT_EQ(elements, all);
}

// A connector that cannot be set up (a LINK of zero length, which `check` reports first) stops
// only the plan of the rank that holds it, with the error the whole plan gives: the run takes
// that of the lowest failing rank (run_command.cpp), the first in element order.
TEST(RowAssembly, AConnectorThatCannotBeSetUpFailsTheRankThatHoldsIt) {
  CheckedDeck deck;
  read_deck_text("link.inp",
                 "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 0., 0.\n"
                 "*ELEMENT, TYPE=CONN3D2, ELSET=A\n1, 1, 2\n2, 1, 3\n"
                 "*ELEMENT, TYPE=CONN3D2, ELSET=L\n3, 2, 3\n"
                 "*CONNECTOR SECTION, ELSET=A\nAXIAL,\n*CONNECTOR SECTION, ELSET=L\nLINK,\n"
                 "*BOUNDARY\n1, 1, 3\n*STEP\n*STATIC\n*END STEP\n",
                 deck.sources, deck.model, deck.sink);
  ASSERT_TRUE(deck.first(DiagCode::link_zero_length)) << deck.dump();
  std::string whole_error;
  ASSERT_FALSE(build_analysis_plan(deck.model, &whole_error));
  EXPECT_NE(whole_error.find("connector element 3: link-zero-length"), std::string::npos)
      << whole_error;
  for (int rank = 0; rank < 3; ++rank) {
    const PlanShare share{rank, 3};
    std::string error;
    const std::optional<AnalysisPlan> plan = build_analysis_plan(deck.model, &error, &share);
    EXPECT_EQ(plan.has_value(), rank != 2) << rank;
    if (!plan) {
      EXPECT_EQ(error, whole_error);
    }
  }
}

// The matrix `m` stands for, dense.
Eigen::MatrixXd dense(const SparseMatrix& m) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(m.n, m.n);
  for (int j = 0; j < m.n; ++j) {
    for (int p = m.col_ptr[j]; p < m.col_ptr[j + 1]; ++p) {
      out(m.row_idx[p], j) += m.values[p];
      if (m.symmetric_upper && m.row_idx[p] != j) out(j, m.row_idx[p]) += m.values[p];
    }
  }
  return out;
}

TEST(RowAssembly, RankPartsOfTheTangentSumToTheSerialTangent) {
  const Square square;
  ASSERT_TRUE(square.whole);
  const CheckedDeck& deck = square.deck;
  const std::optional<AnalysisPlan>& whole = square.whole;
  std::string error;
  // The ground node 5 held: its rows are the identity, which only their owner adds.
  const auto hold_ground = [&](ConnectorSystem& system) {
    for (int dof = 1; dof <= 3; ++dof)
      system.conditions().prescribe(whole->dofs.equation(4, dof), 0.0);
  };
  ConnectorSystem serial(deck.model, *whole);
  hold_ground(serial);
  // A state away from the initial one, the same for every system: SPRINGA's tangent turns with
  // the springs under NLGEOM.
  serial.set_nlgeom(true);
  Eigen::VectorXd dx(serial.size());
  for (int i = 0; i < dx.size(); ++i) dx[i] = 0.01 * std::sin(1.7 * i + 0.3);
  serial.apply_correction(dx);
  SparseMatrix k = serial.pattern();
  Eigen::VectorXd r(serial.size());
  ASSERT_TRUE(serial.evaluate(r, &k).ok);
  const Eigen::MatrixXd expected = dense(k);
  constexpr int kRanks = 3;
  Eigen::MatrixXd summed = Eigen::MatrixXd::Zero(k.n, k.n);
  for (int rank = 0; rank < kRanks; ++rank) {
    const PlanShare share{rank, kRanks};
    const std::optional<AnalysisPlan> plan = build_analysis_plan(deck.model, &error, &share);
    ASSERT_TRUE(plan) << error;
    PartCommunicator communicator(rank, kRanks);
    ConnectorSystem part(deck.model, *plan);
    part.distribute(communicator, true);
    hold_ground(part);
    part.set_nlgeom(true);
    part.apply_correction(dx);
    SparseMatrix k_part = part.pattern();
    ASSERT_TRUE(k_part.partial());
    Eigen::VectorXd r_part(part.size());
    ASSERT_TRUE(part.evaluate(r_part, &k_part).ok);
    summed += dense(k_part);
  }
  // Sums of the same element terms in another order: round-off of the largest entry.
  EXPECT_LE((summed - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace clinch
