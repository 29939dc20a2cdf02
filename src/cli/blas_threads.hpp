// OpenBLAS starts its worker threads when it is loaded, and an idle worker spins (sched_yield)
// for about 0.1 s before it sleeps. `clinch check` never calls BLAS, and on a small machine the
// spinning worker takes the core the reader needs (perf: 15% of a 10⁴-connector check).
#pragma once

namespace clinch {

// Stops OpenBLAS's worker threads when OpenBLAS is linked; it starts them again on its next
// threaded call. Does nothing with another BLAS.
void stop_idle_blas_threads();

}  // namespace clinch
