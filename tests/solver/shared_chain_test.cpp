// The multilevel cycle truncates the chain's second-finest matrix in place: after the cycle is
// gone the chain must be the untruncated Galerkin chain again, bit for bit, and a cycle given a
// shared chain must produce the same iterates as one that computes its own.
#include <gtest/gtest.h>

#include "contact_problems.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

bool identical(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.nonZeros() != b.nonZeros()) return false;
  for (int k = 0; k <= a.outerSize(); ++k)
    if (a.outerIndexPtr()[k] != b.outerIndexPtr()[k]) return false;
  for (Eigen::Index k = 0; k < a.nonZeros(); ++k)
    if (a.innerIndexPtr()[k] != b.innerIndexPtr()[k] || a.valuePtr()[k] != b.valuePtr()[k])
      return false;
  return true;
}

TEST(SharedChain, ATruncatingCycleLeavesTheChainAsItFoundIt) {
  const Discretization<2> disc(build_mesh_hierarchy(make_hertz({.size = 0.1}), 3),
                               testing::hertz(1.0));
  const LevelHierarchy h = disc.build_level_hierarchy();
  const BoxQp& qp = disc.problem().qp;
  auto chain = std::make_shared<GalerkinChain>(galerkin_chain(qp.A, h));
  const GalerkinChain untouched = galerkin_chain(qp.A, h);
  Vector x_shared = Vector::Zero(qp.size()), x_own = Vector::Zero(qp.size());
  Vector r_shared = qp.b, r_own = qp.b;
  int truncated_cycles = 0;
  {
    MultilevelCycle shared(qp, h, MultilevelOptions{}, chain);
    MultilevelCycle own(qp, h, MultilevelOptions{});
    for (int k = 0; k < 8; ++k) {
      shared.nonlinear_cycle(x_shared, r_shared);
      own.nonlinear_cycle(x_own, r_own);
      int active = 0;
      for (int i = 0; i < qp.size(); ++i)
        active += is_at_bound(x_shared[i], qp.lower[i], qp.upper[i]);
      truncated_cycles += active > 0;
      ASSERT_EQ(x_shared, x_own) << "cycle " << k;
    }
    EXPECT_GE(shared.statistics().galerkin_rebuilds, 3);  // several active sets were truncated
  }
  EXPECT_GE(truncated_cycles, 6);
  ASSERT_EQ(chain->matrices.size(), untouched.matrices.size());
  for (std::size_t j = 0; j < untouched.matrices.size(); ++j)
    EXPECT_TRUE(identical(chain->matrices[j], untouched.matrices[j])) << "level " << j;
}

TEST(SharedChain, AChainFormedOnlyAtTheTopIsCompletedWhenACycleNeedsIt) {
  // Adaptive steps after the first pass a chain with only the second-finest matrix: a cycle that
  // runs untruncated (here the obstacle is moved away, so no bound is ever reached) forms the
  // rest on demand, and must produce the iterates, and leave the chain, of one given the whole
  // chain.
  const Discretization<2> disc(build_mesh_hierarchy(make_hertz({.size = 0.1}), 3),
                               testing::hertz(1.0));
  const LevelHierarchy h = disc.build_level_hierarchy();
  BoxQp qp = disc.problem().qp;
  for (int i = 0; i < qp.size(); ++i)
    if (is_bounded_above(qp.upper[i])) qp.upper[i] += 1.0;
  auto top_only = std::make_shared<GalerkinChain>(galerkin_chain(qp.A, h, 1));
  auto whole = std::make_shared<GalerkinChain>(galerkin_chain(qp.A, h));
  ASSERT_GE(top_only->matrices.size(), 3u);
  EXPECT_EQ(top_only->matrices[0].rows(), 0) << "formed before it was needed";
  Vector x_lazy = Vector::Zero(qp.size()), x_whole = Vector::Zero(qp.size());
  Vector r_lazy = qp.b, r_whole = qp.b;
  {
    MultilevelCycle lazy(qp, h, MultilevelOptions{}, top_only);
    MultilevelCycle eager(qp, h, MultilevelOptions{}, whole);
    for (int k = 0; k < 4; ++k) {
      lazy.nonlinear_cycle(x_lazy, r_lazy);
      eager.nonlinear_cycle(x_whole, r_whole);
      ASSERT_EQ(x_lazy, x_whole) << "cycle " << k;
    }
  }
  for (std::size_t j = 0; j < whole->matrices.size(); ++j)
    EXPECT_TRUE(identical(top_only->matrices[j], whole->matrices[j])) << "level " << j;
}

}  // namespace
}  // namespace fosls
