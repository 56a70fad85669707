#pragma once
// Thread count of the parallel patch solves (TBB). The BLAS of the sparse factorisation keeps a
// fixed count (solver/blas_threads.h), so results do not depend on this one.
namespace sdog::cli {

/// n >= 1 threads; 0 = one per core. Lasts for the life of the process.
void set_thread_count(int n);

}  // namespace sdog::cli
