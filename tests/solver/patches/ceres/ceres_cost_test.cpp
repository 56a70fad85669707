// Residual blocks as Ceres cost functions (ceres_cost.h).
#include <gtest/gtest.h>

#include "solver/patches/ceres/ceres_cost.h"
#include "tests/solver/patch_case.h"

namespace sdog {
namespace {

using test::PatchCase;

TEST(TermCost, OffsetShiftsResidualsNotJacobians) {
  const PatchCase s("one_curve.svg", {15, 11});
  const Term& dog = s.problem->dog;
  const Dofs x = s.bent() + 0.01 * Dofs::Ones(s.bent().size());
  const int b = 0, k = dog.block_size(b), m = dog.residual_count(b);
  std::vector<double> offset(m);
  for (int i = 0; i < m; ++i) offset[i] = 0.1 * (i + 1);
  TermCost plain(dog, b, 4.0), shifted(dog, b, 4.0, offset.data());
  std::vector<const double*> params;
  for (int j = 0; j < k; ++j) params.push_back(x.data() + 3 * dog.block_vertices(b)[j]);
  std::vector<double> r1(m), r2(m), J1(3 * m * k), J2(3 * m * k);
  std::vector<double*> j1, j2;
  for (int j = 0; j < k; ++j) {
    j1.push_back(J1.data() + 3 * m * j);
    j2.push_back(J2.data() + 3 * m * j);
  }
  ASSERT_TRUE(plain.Evaluate(params.data(), r1.data(), j1.data()));
  ASSERT_TRUE(shifted.Evaluate(params.data(), r2.data(), j2.data()));
  for (int i = 0; i < m; ++i) EXPECT_NEAR(r2[i], r1[i] - 2.0 * offset[i], 1e-15);
  EXPECT_EQ(J1, J2);
  shifted.set_weight(9.0);
  ASSERT_TRUE(shifted.Evaluate(params.data(), r2.data(), nullptr));
  for (int i = 0; i < m; ++i) EXPECT_NEAR(r2[i], 1.5 * r1[i] - 3.0 * offset[i], 1e-14);
}

}  // namespace
}  // namespace sdog
