// CHOLMOD's failures are seen (solvers/cholmod_checks.hpp): an out-of-memory status becomes
// std::bad_alloc, another error status an exception, and a matrix that is not positive definite
// the `false` of a checked factorisation — none of them a factor that looks computed.

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>

#include "solvers/cholmod_checks.hpp"

namespace fosls {
namespace {

SparseMatrix tridiagonal(int n, double diagonal) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, diagonal);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST(CholmodChecks, StatusesMapToTheirFailures) {
  cholmod_common c;
  c.status = CHOLMOD_OK;
  EXPECT_NO_THROW(check_cholmod_status(c, "a call"));
  c.status = CHOLMOD_NOT_POSDEF;  // a warning: read from info()
  EXPECT_NO_THROW(check_cholmod_status(c, "a call"));
  c.status = CHOLMOD_OUT_OF_MEMORY;
  EXPECT_THROW(check_cholmod_status(c, "a call"), std::bad_alloc);
  c.status = CHOLMOD_TOO_LARGE;
  EXPECT_THROW(check_cholmod_status(c, "a call"), std::bad_alloc);
  c.status = CHOLMOD_INVALID;
  EXPECT_THROW(check_cholmod_status(c, "a call"), std::runtime_error);
}

TEST(CholmodChecks, ADefiniteMatrixSolvesAndAnIndefiniteOneSaysSo) {
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt;
  ASSERT_TRUE(compute_checked(llt, tridiagonal(50, 2.5)));
  const Vector b = Vector::Ones(50);
  const Vector x = solve_checked(llt, b);
  EXPECT_LT((tridiagonal(50, 2.5) * x - b).norm(), 1e-12);
  Eigen::CholmodSupernodalLLT<SparseMatrix> indefinite;
  EXPECT_FALSE(compute_checked(indefinite, tridiagonal(50, 1.0)));  // λ_min = 1 − 2cos(π/51) < 0
}

}  // namespace
}  // namespace fosls
