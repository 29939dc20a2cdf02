// A CHOLMOD view of a SparseMatrix's arrays, without copying. stype = 1: CHOLMOD reads the upper
// triangle only, so a full symmetric matrix is viewed the same way. CHOLMOD does not write to its
// input; the casts only satisfy its non-const C interface. `xtype` CHOLMOD_PATTERN views the
// pattern alone (an analysis), CHOLMOD_REAL the values too.
#pragma once

#include <cholmod.h>

#include <cstddef>

#include "src/linalg/sparse_matrix.hpp"

namespace clinch {

inline cholmod_sparse cholmod_view(const SparseMatrix& m, int xtype) {
  cholmod_sparse a{};
  a.nrow = a.ncol = static_cast<std::size_t>(m.n);
  a.nzmax = static_cast<std::size_t>(m.nonzeros());
  a.p = const_cast<int*>(m.col_ptr.data());
  a.i = const_cast<int*>(m.row_idx.data());
  a.x = xtype == CHOLMOD_PATTERN ? nullptr : const_cast<double*>(m.values.data());
  a.stype = 1;
  a.itype = CHOLMOD_INT;
  a.xtype = xtype;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

}  // namespace clinch
