// The start of an adaptive step: a solution carried to the bisected mesh is the same function,
// so on straight boundaries (nested spaces, the same data) the functional does not change.
// Refining next to the Dirichlet boundary is the case that failed: the new free vertices there
// interpolate prescribed values, which the free-to-free transfer of the multilevel cycle drops.
#include <gtest/gtest.h>

#include "assembly/solution_prolongation.hpp"
#include "contact_problems.hpp"
#include "mesh/bisection.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

/// Triangles of `mesh` with a vertex within `distance` of the line y = `y`.
std::vector<int> triangles_near(const Mesh& mesh, double y, double distance) {
  std::vector<int> near;
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int v : mesh.triangle(t))
      if (std::abs(mesh.vertex(v).y() - y) <= distance) {
        near.push_back(t);
        break;
      }
  return near;
}

TEST(SolutionProlongation, KeepsTheFunctionalNextToDirichletAndContactBoundaries) {
  // A plane obstacle: the gap is linear along the bottom, so nothing of the data changes with
  // the mesh either.
  const ProblemData<2> data = testing::flat_square(1.0);
  MeshHierarchy meshes = build_mesh_hierarchy(make_square({.size = 0.25}), 1);
  BisectionState state = longest_edge_state(meshes.finest(), 2);
  // Two steps at the Dirichlet top (y = 1), two at the contact bottom (y = 0).
  for (double y : {1.0, 1.0, 0.0, 0.0})
    refine_finest_level(meshes, state, triangles_near(meshes.finest(), y, 1e-12));
  for (int top = 2; top < meshes.num_levels(); ++top) {
    MeshHierarchy coarse_meshes = meshes, fine_meshes = meshes;
    coarse_meshes.meshes.resize(top);
    coarse_meshes.maps.resize(top);
    fine_meshes.meshes.resize(top + 1);
    fine_meshes.maps.resize(top + 1);
    const Discretization coarse(coarse_meshes, data), fine(fine_meshes, data);
    SolverOptions options;
    options.method = SolverMethod::kPdas;
    Vector x;
    solve_box_qp(coarse.problem().qp, LevelHierarchy{}, options, {}, x);
    const Vector full = coarse.assembler().full_vector(coarse.problem(), x);
    const Vector xf = prolongate_to_finest(fine, full);
    const BoxQp& qc = coarse.problem().qp;
    const BoxQp& qf = fine.problem().qp;
    // J is a small difference of O(xᵀAx) terms: compared at the rounding of those.
    const double scale = x.dot(qc.A * x);
    EXPECT_NEAR(qf.energy(xf), qc.energy(x), 1e-12 * scale) << "level " << top;
    EXPECT_GT(qc.energy(x), 1e-6 * scale) << "level " << top;  // J itself is not rounding
    EXPECT_TRUE(qf.feasible(xf)) << "level " << top;           // linear gap: no clipping needed
  }
}

TEST(SolutionProlongation, RefusesAVectorOfTheWrongLevel) {
  const ProblemData<2> data = testing::signorini_square(1.0);
  const Discretization disc(build_mesh_hierarchy(make_square({.size = 0.5}), 1), data);
  EXPECT_THROW(prolongate_to_finest(disc, Vector::Zero(disc.space(0).num_free())),
               std::invalid_argument);
}

}  // namespace
}  // namespace fosls
