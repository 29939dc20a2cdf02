// Freed heap memory kept for the next allocation (docs/performance.md "Heap reuse"). A sparse
// factorization allocates its work space and frees it again at every Newton iteration. glibc
// gives such blocks back to the kernel when they sit at the top of the heap (its trim threshold
// follows the largest block mapped so far), so that each factorization of a small model pays
// again for the page faults of touching fresh memory: UMFPACK on the 726 equations of the
// 40-window four-bar mechanism spent more time in page faults than in arithmetic.
#pragma once

namespace clinch {

// Blocks up to 32 MB come from the heap, and up to 64 MB of free heap top is kept rather than
// trimmed (glibc only; elsewhere nothing). Call before anything is allocated that should follow it.
void keep_freed_heap_for_reuse();

}  // namespace clinch
