#include "src/cli/heap_reuse.hpp"

#include <cstdlib>  // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace clinch {

void keep_freed_heap_for_reuse() {
#if defined(__GLIBC__)
  // Fixing the mmap threshold at glibc's own upper bound for its dynamic threshold keeps the
  // trim threshold where it is set here, rather than at twice the last freed mapping.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

}  // namespace clinch
