// Where every element's local matrix goes in the global one, for one storage: the upper triangle
// when every law of a step is symmetric (CHOLMOD), the full pattern otherwise (UMFPACK). Built
// once per storage a run needs; the scatter is then a flat loop over precomputed positions.
#pragma once

#include <vector>

#include "src/assembly/analysis_plan.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {

struct AssemblyPattern {
  bool symmetric = true;
  SparseMatrix matrix;  // values zero
  // Positions into matrix.values of each element's local entries, column by column: the upper
  // triangle (a ≤ b, count·(count+1)/2 entries) when symmetric, all count² otherwise. Connectors
  // first, then springs, each from its offset below (connector c's at
  // connector_offset[c − first_connector]).
  std::vector<int> positions;
  std::vector<std::size_t> connector_offset, spring_offset;
  std::size_t first_connector = 0, first_spring = 0;
  // Position of each solved equation's diagonal entry (−1 where a rank's part has none).
  std::vector<int> diagonal;

  std::size_t connector_at(std::size_t c) const { return connector_offset[c - first_connector]; }
  std::size_t spring_at(std::size_t s) const { return spring_offset[s - first_spring]; }
};

// A rank's part of the tangent under assembly by rows (docs/parallel.md): its elements, and the
// rows it owns among `ranks` (owned_rows over the pattern's node blocks).
struct RowAssemblyShare {
  ItemRange connectors, springs;
  int rank = 0, ranks = 1;
};

// The whole pattern, or with `share` the pattern of that rank's part (SparseMatrix::partial):
// its elements' entries, the diagonals of its rows, and what is added per row (rotary inertia,
// inertia on dependent DOFs, the curvature of constraints under NLGEOM) where it owns one of
// the rows coupled.
AssemblyPattern build_assembly_pattern(const AnalysisPlan& plan, bool symmetric,
                                       const RowAssemblyShare* share = nullptr);

}  // namespace clinch
