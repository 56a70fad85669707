#pragma once
// Threads of the linear algebra under CHOLMOD's supernodal factorisation.
//
// BLAS: OpenBLAS changes its blocking with the thread count, which changes rounding and hence
// (through the fold tests and line searches) whole runs. The executables therefore fix the count
// (default 2, environment variable SDOG_BLAS_THREADS), independent of the machine and of
// --threads, so the same inputs give the same numbers everywhere. The multi-patch modes use 1 BLAS
// thread per patch factorisation (their parallelism is over patches) and set it at every
// iteration, as the standard mode sets its own count.
//
// OpenMP: Debian's CHOLMOD wraps small copy loops of every supernode in OpenMP regions with a
// fixed team of 4 threads, whatever OMP_NUM_THREADS says. Waking that team per supernode costs more
// than the loops save (docs/design/rejected.md), and a team per patch thread oversubscribes the
// cores. So
// set_blas_threads also makes every OpenMP region run on the calling thread. libgomp keeps that
// limit per thread (a new thread starts from the process defaults), so threads that factorise
// on their own, such as the TBB workers of the patch modes, call serial_openmp_regions() too:
// without it every worker's first factorisation starts a team of 4 OpenMP threads that then spin
// beside the patch solves.
#include <string>

namespace sdog {

/// The count from SDOG_BLAS_THREADS (1..64), else 2.
int default_blas_threads();
/// Sets the BLAS (OpenBLAS) thread count if that BLAS is loaded and turns CHOLMOD's OpenMP
/// regions serial if OpenMP is loaded; returns false if OpenBLAS is not loaded.
bool set_blas_threads(int n);
/// The BLAS in use: OpenBLAS's configuration, which names the kernels it runs
/// (app/blas_kernels.h), or "unknown (not OpenBLAS)".
std::string blas_description();
/// Makes every OpenMP region entered from the calling thread run on that thread (nothing if no
/// OpenMP runtime is loaded).
void serial_openmp_regions();

}  // namespace sdog
