// The node-block property of the equation numbering (DofMap::uniform_node_block), which the
// assembled pattern hands to nodal solvers as SparseMatrix::node_block.
#include <gtest/gtest.h>

#include <stdexcept>

#include "src/assembly/dof_map.hpp"
#include "src/linalg/sparse_matrix.hpp"

namespace clinch {
namespace {

constexpr DofMask kTranslations = 0b000111;
constexpr DofMask kAllSix = 0b111111;
constexpr DofMask kPlanar = 0b100011;  // u1, u2, ur3: a CONN2D2 node

TEST(DofMap, UniformNodesGiveTheirEquationCountAsBlock) {
  // Nodes without equations (0) do not interrupt the blocks: they have no equation to misalign.
  EXPECT_EQ(DofMap({kTranslations, 0, kTranslations, kTranslations}).uniform_node_block(), 3);
  EXPECT_EQ(DofMap({kAllSix, kAllSix}).uniform_node_block(), 6);
  EXPECT_EQ(DofMap({kPlanar, 0, kPlanar}).uniform_node_block(), 3);
}

TEST(DofMap, MixedNodesOrMultipliersGiveBlockOne) {
  EXPECT_EQ(DofMap({kTranslations, kAllSix}).uniform_node_block(), 1);
  // Same count, different DOFs: equation i mod 3 would not be one DOF kind.
  EXPECT_EQ(DofMap({kTranslations, kPlanar}).uniform_node_block(), 1);
  DofMap with_multiplier({kTranslations, kTranslations});
  with_multiplier.add_multiplier(false);
  EXPECT_EQ(with_multiplier.uniform_node_block(), 1);
  EXPECT_EQ(DofMap({0, 0}).uniform_node_block(), 1);
}

TEST(SparseMatrix, NodeBlockMustDivideTheOrder) {
  SparseMatrix m;
  m.n = 4;
  m.symmetric_upper = true;
  m.col_ptr = {0, 1, 2, 3, 4};
  m.row_idx = {0, 1, 2, 3};
  m.values = {1.0, 1.0, 1.0, 1.0};
  m.node_block = 2;
  EXPECT_NO_THROW(validate_pattern(m));
  m.node_block = 3;
  EXPECT_THROW(validate_pattern(m), std::invalid_argument);
  m.node_block = 0;
  EXPECT_THROW(validate_pattern(m), std::invalid_argument);
}

}  // namespace
}  // namespace clinch
