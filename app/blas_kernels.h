#pragma once
// OpenBLAS's kernels for the CPU this runs on.
//
// Debian's OpenBLAS picks its kernels from the CPU model it recognises at load time. On CPUs newer
// than its release it recognises none and falls back to its generic SSE3 kernels ("Prescott"),
// which factorise about 2.5 times slower than its AVX2 kernels ("Haswell") on the same machine.
// Kernels also round differently, so results differ between machines that pick different ones. The
// executables therefore run OpenBLAS's Haswell kernels on every x86-64 CPU with AVX2 and FMA:
// faster on new CPUs and the same numbers on all of them. OPENBLAS_CORETYPE, when set, wins.
namespace sdog {

/// Call first thing in main(). When the CPU has AVX2 and FMA and OPENBLAS_CORETYPE is not set,
/// sets it to Haswell and executes the program again with the same arguments (OpenBLAS reads the
/// variable only when it is loaded); returns when nothing needs to change or that fails.
void use_avx2_blas_kernels(char** argv);

}  // namespace sdog
