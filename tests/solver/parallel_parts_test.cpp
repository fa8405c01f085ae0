// The parts of a solve that run on both cores give the same numbers as on one:
// the pattern-first assembly and the Galerkin product bit for bit, the two-block patch sweep
// bit for bit, because its blocks share no entry of x or r. And the assembled QP is the FOSLS
// functional: J(x) = ½xᵀAx − bᵀx + c equals the element-wise sum at random x, so the in-place
// assembly lost no element contribution and no contact term.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <random>

#include "contact_problems.hpp"
#include "solvers/galerkin_product.hpp"
#include "solvers/smoothers.hpp"

namespace fosls {
namespace {

/// Runs f with `threads` OpenMP threads, then restores the previous count.
template <class F>
auto with_threads(int threads, F f) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  auto out = f();
  omp_set_num_threads(before);
  return out;
}

bool identical(const SparseMatrix& a, const SparseMatrix& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && a.nonZeros() == b.nonZeros() &&
         std::memcmp(a.outerIndexPtr(), b.outerIndexPtr(), (a.cols() + 1) * sizeof(int)) == 0 &&
         std::memcmp(a.innerIndexPtr(), b.innerIndexPtr(), a.nonZeros() * sizeof(int)) == 0 &&
         std::memcmp(a.valuePtr(), b.valuePtr(), a.nonZeros() * sizeof(double)) == 0;
}

bool identical(const Vector& a, const Vector& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

/// The curved-gap square with 5 refinements: 131k DOFs, blocks of about 8000 patches.
Discretization square(int refinements = 5) {
  return Discretization(build_mesh_hierarchy(make_square({.size = 0.25}), refinements),
                        testing::signorini_square(1.0));
}

TEST(ParallelParts, AssemblyIsTheSameBitForBitOnOneAndTwoThreads) {
  const Discretization one = with_threads(1, [] { return square(3); });
  const Discretization two = with_threads(2, [] { return square(3); });
  EXPECT_TRUE(identical(one.problem().qp.A, two.problem().qp.A));
  EXPECT_TRUE(identical(one.problem().qp.b, two.problem().qp.b));
  EXPECT_GT(one.problem().qp.A.nonZeros(), 0);
}

TEST(ParallelParts, AssembledQuadraticProgramIsTheFunctional) {
  for (const bool hertz : {false, true}) {
    const Discretization disc =
        hertz ? Discretization(build_mesh_hierarchy(make_hertz({.size = 0.2}), 1),
                               testing::hertz(std::numeric_limits<double>::infinity()))
              : square(2);
    const BoxQp& qp = disc.problem().qp;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.1, 0.1);
    for (int trial = 0; trial < 3; ++trial) {
      Vector x(qp.size());
      for (int i = 0; i < x.size(); ++i) x[i] = u(rng);
      const double element_sum =
          disc.assembler().functional(disc.assembler().full_vector(disc.problem(), x)).total();
      EXPECT_NEAR(qp.energy(x), element_sum, 1e-10 * std::abs(element_sum))
          << (hertz ? "hertz" : "square") << ", trial " << trial;
    }
  }
}

TEST(ParallelParts, GalerkinProductIsEigensProductAndThreadIndependent) {
  const Discretization disc = square(3);
  const LevelHierarchy h = disc.build_level_hierarchy();
  const SparseMatrix& a = disc.problem().qp.A;
  const SparseMatrix& p = h.levels.back().prolongation;
  const SparseMatrix reference = SparseMatrix(p.transpose()) * (a * p);
  const SparseMatrix one = with_threads(1, [&] { return galerkin_product(a, p); });
  const SparseMatrix two = with_threads(2, [&] { return galerkin_product(a, p); });
  EXPECT_TRUE(identical(one, two));
  EXPECT_LE((one - reference).norm(), 1e-13 * reference.norm());
}

/// Rows of the residual that the patches [begin, end) read or write: the rows of A's columns
/// of their DOFs.
std::vector<char> touched(const SparseMatrix& a, const std::vector<std::vector<int>>& patches,
                          int begin, int end) {
  std::vector<char> rows(a.rows(), 0);
  for (int p = begin; p < end; ++p)
    for (int dof : patches[p])
      for (SparseMatrix::InnerIterator it(a, dof); it; ++it) rows[it.row()] = 1;
  return rows;
}

TEST(ParallelParts, ResidualProductIsEigensAndThreadIndependent) {
  // Above the 20 000-column threshold, so that the two threads split the entries.
  const Discretization disc = square(4);
  const SparseMatrix& a = disc.problem().qp.A;
  ASSERT_GT(a.cols(), 20000);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vector x(a.cols());
  for (int i = 0; i < x.size(); ++i) x[i] = u(rng);
  auto product = [&](int threads) {
    return with_threads(threads, [&] {
      Vector y;
      symmetric_multiply(a, x, y);
      return y;
    });
  };
  const Vector one = product(1), two = product(2), three = product(3);
  EXPECT_TRUE(identical(one, two));
  EXPECT_TRUE(identical(one, three));
  const Vector reference = a * x;
  EXPECT_LE((one - reference).norm(), 1e-14 * reference.norm());
}

TEST(ParallelParts, PatchBlocksShareNoEntryAndSplitTheWorkEvenly) {
  const Discretization disc = square();
  const LevelHierarchy h = disc.build_level_hierarchy();
  const Level& level = h.levels.back();
  const auto [end0, end1] = level.patch_split;
  const int np = static_cast<int>(level.patches.size());
  EXPECT_GE(end0, PatchSmoother::kMinParallelPatches);
  EXPECT_GE(end1 - end0, PatchSmoother::kMinParallelPatches);
  EXPECT_GE(end1 - end0, 0.9 * end0) << "unbalanced blocks";
  EXPECT_LE(np - end1, 0.05 * np) << "separator too large";
  const auto first = touched(disc.problem().qp.A, level.patches, 0, end0);
  const auto second = touched(disc.problem().qp.A, level.patches, end0, end1);
  for (int i = 0; i < disc.problem().qp.size(); ++i)
    ASSERT_FALSE(first[i] && second[i]) << "row " << i << " touched by both blocks";
}

TEST(ParallelParts, TwoThreadPatchSweepIsTheSerialSweep) {
  const Discretization disc = square();
  const LevelHierarchy h = disc.build_level_hierarchy();
  const BoxQp& qp = disc.problem().qp;
  const Level& level = h.levels.back();
  const PatchSmoother smoother(qp.A, level.patches, level.patch_split);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vector start(qp.size());
  for (int i = 0; i < qp.size(); ++i)
    start[i] = is_bounded_above(qp.upper[i]) ? qp.upper[i] - 0.01 * u(rng) : 0.1 * u(rng);
  auto sweeps = [&](int threads) {
    return with_threads(threads, [&] {
      Vector x = start, r = qp.b - qp.A * start;
      for (int s = 0; s < 2; ++s) smoother.sweep(x, r, qp.lower, qp.upper, s == 0);
      return std::make_pair(x, r);
    });
  };
  const auto [x1, r1] = sweeps(1);
  const auto [x2, r2] = sweeps(2);
  EXPECT_TRUE(identical(x1, x2));
  EXPECT_TRUE(identical(r1, r2));
  EXPECT_FALSE(identical(x1, start));
}

}  // namespace
}  // namespace fosls
