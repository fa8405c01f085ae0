// The one hierarchy builder on levels made by newest-vertex bisection of tetrahedra (issue 48,
// docs/method.md §11): the 3D Signorini block (tests/tet_problems.hpp) on the box of refinement
// 1 whose tetrahedra at the centre of the contact face are bisected in three steps (h halved
// there, the rest kept). Its levels' transfers carry the exact face shares, the contact faces kept,
// halved and quartered give contact links of one, two and four children, and local smoothing visits
// the refined region only. mmg keeps J non-increasing and every iterate feasible at every step of
// its cycle, agrees with pdas on the same mesh, and the force is the uniform refinement's to
// within a fraction of the discretisation error between refinements 1 and 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "../sweep_checks.hpp"
#include "../tet_problems.hpp"
#include "assembly/discretization.hpp"
#include "mesh/tet_bisection.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

/// The box's uniform refinement 1, then three bisection steps of the tetrahedra with a vertex on
/// the contact face z = 0 within 0.4 of its centre (where the contact zone is): h halved there
/// after the third, the outer part of the contact face kept or halved by the closure only.
TetHierarchy locally_bisected_box() {
  TetHierarchy h = build_tet_hierarchy(make_box({2, 2, 2}), 1);
  TetBisectionState state = initial_tet_bisection_state(h.finest());
  for (int step = 0; step < kMaxBisectionsPerStep; ++step) {
    const TetMesh& mesh = h.finest();
    std::vector<int> marked;
    for (int t = 0; t < mesh.num_tets(); ++t)
      for (int v : mesh.tet(t)) {
        const Point3& x = mesh.vertex(v);
        if (x.z() == 0.0 && std::hypot(x.x() - 0.5, x.y() - 0.5) <= 0.4) {
          marked.push_back(t);
          break;
        }
      }
    refine_finest_tet_level(h, state, marked);
  }
  return h;
}

/// How many contact links of the bisection levels hold a kept coarse face (one child), a halved
/// or partly quartered one (a pair without partner) and a quartered one (a pair with partner).
struct LinkKinds {
  int kept = 0, pair = 0, partnered = 0;
};

LinkKinds link_kinds(const LevelHierarchy& h) {
  LinkKinds kinds;
  for (std::size_t j = 1; j < h.levels.size(); ++j)
    for (const ContactLink& link : h.levels[j].links) {
      if (link.coarse_sn < 0 || link.fine_sn[0] < 0) continue;
      if (link.fine_sn[1] < 0)
        ++kinds.kept;
      else if (link.partners.empty())
        ++kinds.pair;
      else
        ++kinds.partnered;
    }
  return kinds;
}

Point3 pdas_force(const Discretization<3>& disc) {
  SolverOptions options;
  options.method = SolverMethod::kPdas;
  options.tolerance = 1e-10;
  Vector x = Vector::Zero(disc.problem().qp.size());
  EXPECT_TRUE(solve_box_qp(disc.problem().qp, LevelHierarchy{}, options, {}, x).converged);
  return contact_force(disc.finest_space(), disc.assembler().full_vector(disc.problem(), x),
                       disc.problem().stress_scale);
}

class TetLocalHierarchy : public ::testing::TestWithParam<double> {};

TEST_P(TetLocalHierarchy, MonotoneFeasibleAndForceOfTheUniformRefinement) {
  const double lambda = GetParam();
  const TetHierarchy meshes = locally_bisected_box();
  const int uniform_tets = build_tet_hierarchy(make_box({2, 2, 2}), 2).finest().num_tets();
  ASSERT_GE(meshes.num_levels(), 3);
  EXPECT_LT(meshes.finest().num_tets(), uniform_tets);  // local: fewer than the uniform level
  const Discretization<3> disc(meshes, testing::signorini_block(lambda));
  const BoxQp& qp = disc.problem().qp;
  // Every level (max_share 1), and the solvers' default, levels a factor apart
  // (assembly/solver_levels.hpp): here the two bisection levels below the finest are skipped.
  const LevelHierarchy every_level = disc.build_level_hierarchy(1.0);
  const LevelHierarchy h = disc.build_level_hierarchy();
  ASSERT_EQ(every_level.num_levels(), meshes.num_levels());
  EXPECT_EQ(h.num_levels(), 3);
  EXPECT_EQ(hierarchy_inconsistency(every_level, qp.size()), "");
  EXPECT_EQ(hierarchy_inconsistency(h, qp.size()), "");
  // The bisection levels exercise every kind of link, and local smoothing skips the vertices
  // away from the refined region on the intermediate levels.
  const LinkKinds kinds = link_kinds(every_level);
  EXPECT_GT(kinds.kept + kinds.pair, 0);
  int skipped = 0;
  for (std::size_t j = 2; j + 1 < every_level.levels.size(); ++j)
    skipped += disc.meshes().meshes[j].num_vertices() -
               static_cast<int>(every_level.levels[j].patches.size());
  EXPECT_GT(skipped, 0);
  // Every smoother sweep and coarse correction of the first cycles from zero.
  EXPECT_GE(testing::checked_cycles_from_zero(qp, every_level, 10), 30);
  EXPECT_GE(testing::checked_cycles_from_zero(qp, h, 10), 30);
  const testing::MmgAndPdas every = testing::solve_with_mmg_and_pdas(disc, every_level);
  EXPECT_TRUE(every.mmg.converged);
  EXPECT_NEAR(every.force.z(), every.pdas_force.z(), 1e-6 * every.pdas_force.z());
  EXPECT_LE(every.mmg.iterations, 25);  // 12 and 11 measured
  const testing::MmgAndPdas s = testing::solve_with_mmg_and_pdas(disc, h);
  EXPECT_TRUE(s.mmg.converged);
  EXPECT_TRUE(s.pdas.converged);
  EXPECT_NEAR(s.force.z(), s.pdas_force.z(), 1e-6 * s.pdas_force.z());
  // The same problem on the uniform refinements 1 and 2 of the box.
  const Point3 f1 = pdas_force(Discretization<3>(build_tet_hierarchy(make_box({2, 2, 2}), 1),
                                                 testing::signorini_block(lambda)));
  const Point3 f2 = pdas_force(Discretization<3>(build_tet_hierarchy(make_box({2, 2, 2}), 2),
                                                 testing::signorini_block(lambda)));
  std::printf(
      "λ = %g: %d levels (%d for the solvers), %d unknowns (uniform r = 2: %d tetrahedra, local "
      "%d), links kept %d, "
      "pairs %d, partnered %d, %d vertices not smoothed; mmg %d iterations (%d on every level); "
      "F_z local %.8f, "
      "uniform r = 1 %.8f, r = 2 %.8f\n",
      lambda, meshes.num_levels(), h.num_levels(), qp.size(), uniform_tets,
      meshes.finest().num_tets(), kinds.kept, kinds.pair, kinds.partnered, skipped,
      s.mmg.iterations, every.mmg.iterations, s.force.z(), f1.z(), f2.z());
  // 13 and 13 measured on the solvers' three levels; 57 and 61 on every level with a quarter
  // for every face's share (the red rule).
  EXPECT_LE(s.mmg.iterations, 25);
  EXPECT_LT(std::abs(s.force.z() - f2.z()), 0.5 * std::abs(f1.z() - f2.z()));
}

INSTANTIATE_TEST_SUITE_P(Lambda, TetLocalHierarchy,
                         ::testing::Values(1.0, std::numeric_limits<double>::infinity()));

}  // namespace
}  // namespace fosls
