#pragma once
// Threads of the BLAS under CHOLMOD's supernodal factorisation. OpenBLAS changes its blocking
// with the thread count, which changes rounding and hence (through the fold tests and line
// searches) whole runs. The executables therefore fix the count (default 2, environment variable
// SDOG_BLAS_THREADS), independent of the machine and of --threads, so the same inputs give the
// same numbers everywhere. The multi-patch modes use 1 BLAS thread per patch factorisation
// (their parallelism is over patches) and set it at every iteration, as the standard mode sets
// its own count.
namespace sdog {

/// The count from SDOG_BLAS_THREADS (1..64), else 2.
int default_blas_threads();
/// Sets the BLAS (OpenBLAS) thread count if that BLAS is loaded; returns false otherwise.
bool set_blas_threads(int n);

}  // namespace sdog
