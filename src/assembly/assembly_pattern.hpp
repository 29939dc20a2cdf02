// Where every element's local matrix goes in the global one, for one storage: the upper triangle
// when every law of a step is symmetric (CHOLMOD), the full pattern otherwise (UMFPACK). Built
// once per storage a run needs; the scatter is then a flat loop over precomputed positions.
#pragma once

#include <vector>

#include "src/assembly/analysis_plan.hpp"

namespace clinch {

struct AssemblyPattern {
  bool symmetric = true;
  SparseMatrix matrix;  // values zero
  // Positions into matrix.values of each element's local entries, column by column: the upper
  // triangle (a ≤ b, count·(count+1)/2 entries) when symmetric, all count² otherwise. Connectors
  // first, then springs, each from its offset below.
  std::vector<int> positions;
  std::vector<std::size_t> connector_offset, spring_offset;
  std::vector<int> diagonal;  // position of each solved equation's diagonal entry
};

AssemblyPattern build_assembly_pattern(const AnalysisPlan& plan, bool symmetric);

}  // namespace clinch
