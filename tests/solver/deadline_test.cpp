// solver.time_limit_s before the first iterate: the spaces and the assembly's element loop (of
// triangles, tetrahedra and order 2) poll the run's deadline and throw TimeLimitReached once it has
// passed, and a deadline that does not pass changes nothing (the assembled problem is the same bit
// for bit).
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>

#include "../tet_problems.hpp"
#include "assembly/p2_rt1_assembler.hpp"
#include "contact_problems.hpp"
#include "core/deadline.hpp"

namespace fosls {
namespace {

using Clock = Deadline::Clock;

Discretization square(int refinements, const Deadline& deadline = {}) {
  return Discretization(build_mesh_hierarchy(make_square({.size = 0.25}), refinements),
                        testing::signorini_square(1.0), deadline);
}

bool identical(const SparseMatrix& a, const SparseMatrix& b) {
  return a.nonZeros() == b.nonZeros() && a.cols() == b.cols() &&
         std::memcmp(a.innerIndexPtr(), b.innerIndexPtr(), a.nonZeros() * sizeof(int)) == 0 &&
         std::memcmp(a.valuePtr(), b.valuePtr(), a.nonZeros() * sizeof(double)) == 0;
}

TEST(Deadline, TheElementLoopStopsOnceItHasPassed) {
  const Discretization disc = square(4);  // 8 192 triangles: several polls per thread
  ASSERT_GT(disc.meshes().finest().num_triangles(), 4 * Deadline::kPollEvery);
  try {
    disc.assembler().assemble_system(Deadline(Clock::now()));
    FAIL() << "the assembly ran to its end past its deadline";
  } catch (const TimeLimitReached& e) {
    EXPECT_EQ(e.stage(), "assembling the finest level");
  }
}

// The tetrahedra's and order 2's assemblies share the scatter, and with it the deadline.
TEST(Deadline, TheElementLoopStopsOnceItHasPassedIn3DAndAtOrderTwo) {
  const TetHierarchy tets = build_tet_hierarchy(make_box({2, 2, 2}), 2);  // 3 072 tetrahedra
  ASSERT_GT(tets.finest().num_cells(), 2 * Deadline::kPollEvery);
  const ProblemData<3> block = testing::signorini_block(1.0);
  const FoslsSpace<3> space3(tets.finest(), block.boundary_roles());
  const FoslsAssembler<3> assembler3(space3, block);
  const MeshHierarchy meshes = build_mesh_hierarchy(make_square({.size = 0.25}), 4);
  const ProblemData<2> square = testing::signorini_square(1.0);
  const P2Rt1Space space2(meshes.finest(), square.boundary_roles());
  const P2Rt1Assembler assembler2(space2, square);
  for (int order = 1; order <= 2; ++order) {
    try {
      if (order == 1)
        assembler3.assemble_system(Deadline(Clock::now()));
      else
        assembler2.assemble_system(Deadline(Clock::now()));
      FAIL() << "the assembly ran to its end past its deadline";
    } catch (const TimeLimitReached& e) {
      EXPECT_EQ(e.stage(), "assembling the finest level");
    }
  }
}

TEST(Deadline, TheSpacesAreNotBuiltPastIt) {
  try {
    square(2, Deadline(Clock::now() - std::chrono::seconds(1)));
    FAIL() << "the discretization was built past its deadline";
  } catch (const TimeLimitReached& e) {
    EXPECT_EQ(e.stage(), "building the finite element spaces");
  }
}

TEST(Deadline, ADeadlineThatDoesNotPassChangesNothing) {
  const Discretization none = square(4);
  const Discretization later = square(4, Deadline(Clock::now() + std::chrono::hours(1)));
  EXPECT_TRUE(identical(none.problem().qp.A, later.problem().qp.A));
  const Vector& b0 = none.problem().qp.b;
  const Vector& b1 = later.problem().qp.b;
  ASSERT_EQ(b0.size(), b1.size());
  EXPECT_EQ(std::memcmp(b0.data(), b1.data(), b0.size() * sizeof(double)), 0);
  EXPECT_EQ(none.problem().qp.constant, later.problem().qp.constant);
  EXPECT_FALSE(Deadline().passed());
  EXPECT_NO_THROW(Deadline().check("never"));
}

}  // namespace
}  // namespace fosls
