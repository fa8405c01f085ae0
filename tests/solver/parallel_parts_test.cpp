// The parts of a solve that run on both cores give the same numbers as on one:
// the pattern-first assembly and the Galerkin product bit for bit, the two-block patch sweep
// bit for bit, because its blocks share no entry of x or r. And the assembled QP is the FOSLS
// functional: J(x) = ½xᵀAx − bᵀx + c equals the element-wise sum at random x, so the in-place
// assembly lost no element contribution and no contact term.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <random>

#include "../tet_problems.hpp"
#include "assembly/p2_rt1_assembler.hpp"
#include "assembly/tet_hierarchy.hpp"
#include "contact_problems.hpp"
#include "solvers/galerkin_product.hpp"
#include "solvers/patch_smoother.hpp"

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

// The one scatter (assembly_pattern.hpp) serves the tetrahedra and order 2 as well: the same
// matrix and b on one thread and on two, and order 2's constant, summed cell by cell, too.
TEST(ParallelParts, ThreeDAndOrderTwoAssemblyAreTheSameBitForBitOnOneAndTwoThreads) {
  const TetHierarchy tets = build_tet_hierarchy(make_box({2, 2, 2}), 2);
  const ProblemData<3> block = testing::signorini_block(1.0);
  const FoslsSpace<3> space3(tets.finest(), block.boundary_roles());
  const FoslsAssembler<3> assembler3(space3, block);
  auto assemble3 = [&](int threads) {
    return with_threads(threads, [&] { return assembler3.assemble_system(); });
  };
  const AssembledProblem one3 = assemble3(1), two3 = assemble3(2);
  EXPECT_TRUE(identical(one3.qp.A, two3.qp.A));
  EXPECT_TRUE(identical(one3.qp.b, two3.qp.b));
  EXPECT_GT(one3.qp.A.nonZeros(), 0);

  const MeshHierarchy meshes = build_mesh_hierarchy(make_square({.size = 0.25}), 2);
  const ProblemData<2> square = testing::signorini_square(1.0);
  const P2Rt1Space space2(meshes.finest(), square.boundary_roles());
  const P2Rt1Assembler assembler2(space2, square);
  auto assemble2 = [&](int threads) {
    return with_threads(threads, [&] { return assembler2.assemble_system(); });
  };
  const AssembledProblem one2 = assemble2(1), two2 = assemble2(2);
  EXPECT_TRUE(identical(one2.qp.A, two2.qp.A));
  EXPECT_TRUE(identical(one2.qp.b, two2.qp.b));
  EXPECT_EQ(one2.qp.constant, two2.qp.constant);
  EXPECT_NE(one2.qp.constant, 0.0);
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
      // NaN where a share would leave an entry unwritten.
      Vector y = Vector::Constant(a.cols(), std::numeric_limits<double>::quiet_NaN());
      symmetric_multiply(a, x, y);
      return y;
    });
  };
  // Two threads must really run, or the comparison below would hold trivially.
  ASSERT_GE(with_threads(2, [] { return omp_get_max_threads(); }), 2);
  const Vector one = product(1), two = product(2), three = product(3);
  EXPECT_TRUE(identical(one, two));
  EXPECT_TRUE(identical(one, three));
  const Vector reference = a * x;
  EXPECT_LE((one - reference).norm(), 1e-14 * reference.norm());
}

/// Checks that the shares of `outer` cover 0..n in order and hold nnz / shares entries each,
/// up to one column.
void expect_balanced_cover(const std::vector<int>& outer, int shares) {
  const int n = static_cast<int>(outer.size()) - 1;
  int covered = 0, widest_column = 0;
  for (int i = 0; i < n; ++i) widest_column = std::max(widest_column, outer[i + 1] - outer[i]);
  for (int t = 0; t < shares; ++t) {
    const auto [begin, end] = entry_balanced_columns(outer.data(), n, t, shares);
    EXPECT_EQ(begin, covered) << "share " << t << " of " << shares;
    EXPECT_LE(begin, end);
    covered = end;
    const double entries = outer[end] - outer[begin], fair = double(outer[n]) / shares;
    EXPECT_LE(std::abs(entries - fair), widest_column + 1.0) << "share " << t << " of " << shares;
  }
  EXPECT_EQ(covered, n);
}

TEST(ParallelParts, EntryBalancedSharesCoverEveryColumnOnce) {
  // Columns of 4 entries then of 2 (the u and σ DOFs of a FOSLS matrix), empty columns at the
  // start, in the middle and at the end, fewer columns than shares, and no entries at all.
  std::vector<int> uneven{0};
  for (int i = 0; i < 3; ++i) uneven.push_back(0);
  for (int i = 0; i < 40; ++i) uneven.push_back(uneven.back() + (i < 20 ? 4 : 2));
  for (int i = 0; i < 5; ++i) uneven.push_back(uneven.back());
  for (int i = 0; i < 10; ++i) uneven.push_back(uneven.back() + 3);
  for (int i = 0; i < 4; ++i) uneven.push_back(uneven.back());
  for (int shares : {1, 2, 3, 7, 64}) expect_balanced_cover(uneven, shares);
  expect_balanced_cover({0, 5, 9}, 5);
  expect_balanced_cover({0, 0, 0, 0}, 2);
  // Two shares of the uneven columns: the first ends where half the entries are, well before
  // half the columns (the point of balancing by entries).
  const int n = static_cast<int>(uneven.size()) - 1;
  EXPECT_LT(entry_balanced_columns(uneven.data(), n, 0, 2).second, n / 2);
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
}

/// How many levels are swept on two threads, each checked to have blocks that share no entry of
/// their matrix (the finest `a`, then Galerkin products down the hierarchy).
int levels_with_independent_blocks(const LevelHierarchy& h, SparseMatrix a) {
  int checked = 0;
  for (int j = h.num_levels() - 1; j >= 0; --j) {
    const Level& level = h.levels[j];
    const auto [end0, end1] = level.patch_split;
    if (std::min(end0, end1 - end0) >= PatchSmoother::kMinParallelPatches) {
      ++checked;
      const auto first = touched(a, level.patches, 0, end0);
      const auto second = touched(a, level.patches, end0, end1);
      for (int i = 0; i < a.rows(); ++i) {
        EXPECT_FALSE(first[i] && second[i]) << "level " << j << ", row " << i;
        if (first[i] && second[i]) return checked;
      }
    }
    if (j > 0) a = galerkin_product(a, level.prolongation);
  }
  return checked;
}

TEST(ParallelParts, PatchBlocksShareNoEntryOnEveryLevelSweptOnTwoThreads) {
  // Coarse levels are swept on two threads too once both blocks reach kMinParallelPatches; their
  // matrices are Galerkin products (truncation only removes entries), so the blocks must be
  // independent in P_jᵀ A P_j, not only in the finest A.
  const Discretization disc = square();
  const LevelHierarchy h = disc.build_level_hierarchy();
  const int checked = levels_with_independent_blocks(h, disc.problem().qp.A);
  EXPECT_GE(checked, 3) << "the finest level and at least two coarse levels";
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

TEST(ParallelParts, ThreeDPatchBlocksShareNoEntryAndTheTwoThreadSweepIsTheSerialOne) {
  // The 3D Signorini block at refinements 3 (159k DOFs): the same split, on the tetrahedra's
  // vertex graph, on every level swept on two threads.
  const TetDiscretization disc(build_tet_hierarchy(make_box({2, 2, 2}), 3),
                               testing::signorini_block(1.0));
  const LevelHierarchy h = disc.build_level_hierarchy();
  const int checked = levels_with_independent_blocks(h, disc.problem().qp.A);
  EXPECT_GE(checked, 1);
  const BoxQp& qp = disc.problem().qp;
  const PatchSmoother smoother(qp.A, h.levels.back().patches, h.levels.back().patch_split);
  auto sweep = [&](int threads) {
    return with_threads(threads, [&] {
      Vector x = Vector::Zero(qp.size()), r = qp.b;
      smoother.sweep(x, r, qp.lower, qp.upper, true);
      return std::make_pair(x, r);
    });
  };
  const auto [x1, r1] = sweep(1);
  const auto [x2, r2] = sweep(2);
  EXPECT_TRUE(identical(x1, x2));
  EXPECT_TRUE(identical(r1, r2));
}

}  // namespace
}  // namespace fosls
