#include "src/linalg/fill_estimate.hpp"

#include <cholmod.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "src/linalg/cholmod_view.hpp"

namespace clinch {
namespace {

// The upper triangle of the graph whose vertices are the blocks of `block` consecutive
// equations, compressed by columns with sorted rows.
SparseMatrix block_graph(const SparseMatrix& pattern, int block) {
  SparseMatrix graph;
  graph.n = pattern.n / block;
  graph.symmetric_upper = true;
  graph.col_ptr.assign(1, 0);
  graph.col_ptr.reserve(static_cast<std::size_t>(graph.n) + 1);
  graph.row_idx.reserve(static_cast<std::size_t>(pattern.nonzeros() / block));
  std::vector<int> seen(static_cast<std::size_t>(graph.n), -1);
  for (int node = 0; node < graph.n; ++node) {
    const auto first = graph.row_idx.size();
    for (int column = node * block; column < (node + 1) * block; ++column) {
      for (int k = pattern.col_ptr[column]; k < pattern.col_ptr[column + 1]; ++k) {
        const int row = pattern.row_idx[k] / block;
        if (row > node || seen[row] == node) continue;
        seen[row] = node;
        graph.row_idx.push_back(row);
      }
    }
    std::sort(graph.row_idx.begin() + static_cast<std::ptrdiff_t>(first), graph.row_idx.end());
    graph.col_ptr.push_back(static_cast<int>(graph.row_idx.size()));
  }
  return graph;
}

double amd_cholesky_flops(const SparseMatrix& upper) {
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_sparse a = cholmod_view(upper, CHOLMOD_PATTERN);
  cholmod_factor* factor = cholmod_analyze(&a, &common);
  const double flops = factor != nullptr ? common.fl : std::numeric_limits<double>::infinity();
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
  return flops;
}

}  // namespace

double estimated_cholesky_flops(const SparseMatrix& pattern) {
  if (pattern.n == 0) return 0.0;
  const int block = pattern.node_block;
  if (block <= 1 || pattern.n % block != 0) return amd_cholesky_flops(pattern);
  return static_cast<double>(block) * block * block * amd_cholesky_flops(block_graph(pattern, block));
}

}  // namespace clinch
