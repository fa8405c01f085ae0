// The invariant checks: hierarchy_inconsistency finds a broken level hierarchy, and in a build
// with FOSLS_CHECKS (Debug, tests/run.sh --sanitize) building a cycle on one throws.
#include <gtest/gtest.h>

#include "../solver/contact_problems.hpp"
#include "core/fosls_assert.hpp"
#include "solvers/multilevel_cycle.hpp"

namespace fosls {
namespace {

TEST(Invariants, HierarchyOfADiscretizationIsConsistent) {
  Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.5}), 2),
                         testing::signorini_square(1.0));
  const LevelHierarchy h = disc.build_level_hierarchy();
  EXPECT_EQ(hierarchy_inconsistency(h, disc.problem().qp.size()), "");
}

TEST(Invariants, BrokenHierarchiesAreNamed) {
  Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.5}), 2),
                         testing::signorini_square(1.0));
  const int n = disc.problem().qp.size();
  LevelHierarchy h = disc.build_level_hierarchy();
  EXPECT_NE(hierarchy_inconsistency(h, n + 1).find("finest level's size"), std::string::npos);
  LevelHierarchy bad_patch = h;
  bad_patch.levels[1].patches[0].push_back(bad_patch.levels[1].num_dofs);
  EXPECT_NE(hierarchy_inconsistency(bad_patch, n).find("patch DOF"), std::string::npos);
  LevelHierarchy bad_p = h;
  bad_p.levels[1].prolongation.resize(3, 3);
  EXPECT_NE(hierarchy_inconsistency(bad_p, n).find("does not map"), std::string::npos);
  if constexpr (kChecksEnabled) {
    EXPECT_THROW(MultilevelCycle(disc.problem().qp, bad_patch, MultilevelOptions{}),
                 InvariantError);
  }
}

TEST(Invariants, AFailedCheckNamesTheCondition) {
  if constexpr (!kChecksEnabled) GTEST_SKIP() << "FOSLS_CHECKS is off in this build";
  try {
    FOSLS_ASSERT(1 + 1 == 3, "arithmetic");
    FAIL();
  } catch (const InvariantError& e) {
    EXPECT_NE(std::string(e.what()).find("1 + 1 == 3"), std::string::npos);
  }
}

}  // namespace
}  // namespace fosls
