// base/errors.h: every error is an sdog::Error whose kind gives the exit code, and throw_error
// throws the shorthand of its kind, so that a catch of that shorthand catches it.
#include "base/errors.h"

#include <gtest/gtest.h>

namespace sdog {
namespace {

TEST(Errors, UsageErrorsExitWith2AndTheOthersWith1) {
  EXPECT_EQ(exit_code(ErrorKind::kUsage), 2);
  EXPECT_EQ(exit_code(ErrorKind::kInput), 1);
  EXPECT_EQ(exit_code(ErrorKind::kOutput), 1);
  EXPECT_EQ(exit_code(ErrorKind::kSolver), 1);
}

TEST(Errors, ThrowErrorThrowsTheShorthandOfItsKind) {
  EXPECT_THROW(throw_error(ErrorKind::kInput, "a"), InputError);
  EXPECT_THROW(throw_error(ErrorKind::kUsage, "b"), UsageError);
  EXPECT_THROW(throw_error(ErrorKind::kOutput, "c"), OutputError);
  EXPECT_THROW(throw_error(ErrorKind::kSolver, "d"), SolverError);
  try {
    throw_error(ErrorKind::kUsage, "--rho: must be positive");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kUsage);
    EXPECT_STREQ(e.what(), "--rho: must be positive");
  }
}

TEST(Errors, EveryShorthandIsAnErrorOfItsKind) {
  EXPECT_EQ(InputError("x").kind(), ErrorKind::kInput);
  EXPECT_EQ(UsageError("x").kind(), ErrorKind::kUsage);
  EXPECT_EQ(OutputError("x").kind(), ErrorKind::kOutput);
  EXPECT_EQ(SolverError("x").kind(), ErrorKind::kSolver);
}

}  // namespace
}  // namespace sdog
