#include "src/cli/blas_threads.hpp"

// OpenBLAS's own shutdown entry (exported by libopenblas; its exec_blas re-initialises the
// thread pool when it finds it shut down). Weak: absent with another BLAS.
extern "C" int blas_thread_shutdown_(void) __attribute__((weak));

namespace clinch {

void stop_idle_blas_threads() {
  if (blas_thread_shutdown_) blas_thread_shutdown_();
}

}  // namespace clinch
