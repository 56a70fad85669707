// main() of the GoogleTest programs: the executables' OpenBLAS kernels, so that the solver tests
// compute what sdog computes on the same machine.
#include <gtest/gtest.h>

#include "app/blas_kernels.h"

int main(int argc, char** argv) {
  sdog::use_avx2_blas_kernels(argv);
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
