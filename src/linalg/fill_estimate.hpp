// A cheap prediction of what a sparse factorization of a pattern costs, for the automatic
// choice of the linear solver (docs/parallel.md "The automatic choice"): it must cost a small
// fraction of the analysis it may make unnecessary.
// - One ordering (AMD) instead of the two a CHOLMOD analysis tries (AMD and METIS, the second
//   by far the dearer), and no supernodal structure.
// - On the graph of the nodes when the equations come in node blocks of b (a translational
//   lattice: b = 3): a column of the node graph with c entries stands for b columns of about
//   b·c entries, so the factorization's flops are about b³ times the node graph's.
// AMD's factor is denser than METIS's on 3-D meshes (about 3× the flops on the lattices of
// docs/benchmarks.md) and about the same on chains and small models, so the estimate is an upper
// bound of what CHOLMOD's analysis would find, within a small factor.
#pragma once

#include "src/linalg/sparse_matrix.hpp"

namespace clinch {

// Flops of one Cholesky factorization of the symmetric pattern (upper storage, or the upper
// triangle of a full, structurally symmetric pattern), AMD-ordered; +infinity when the factor
// would not fit CHOLMOD's 32-bit indices.
double estimated_cholesky_flops(const SparseMatrix& pattern);

}  // namespace clinch
