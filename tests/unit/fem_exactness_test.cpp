// Exactness of P1, RT0 and the level transfers.
#include <gtest/gtest.h>

#include "fem/fosls_space.hpp"
#include "fem/transfer.hpp"
#include "mesh/bisection.hpp"
#include "mesh/builtin_meshes.hpp"
#include "mesh/refinement.hpp"
#include "perturbed_square.hpp"
#include "post/fe_field.hpp"

namespace fosls {
namespace {

const Eigen::Matrix2d kGrad = (Eigen::Matrix2d() << 0.3, -1.2, 0.7, 2.1).finished();
const Eigen::Vector2d kShift(0.4, -0.25);
const Eigen::Matrix2d kSigma = (Eigen::Matrix2d() << 1.5, -0.4, 0.9, -2.2).finished();

/// Interpolant of u(x) = kShift + kGrad x and σ = kSigma (Cartesian, no contact groups).
Vector interpolate(const FoslsSpace<2>& s) {
  const Mesh& m = s.mesh();
  Vector x(s.num_dofs());
  for (int v = 0; v < m.num_vertices(); ++v) {
    Eigen::Vector2d u = kShift + kGrad * m.vertex(v);
    x[s.u_dof(v, 0)] = u[0];
    x[s.u_dof(v, 1)] = u[1];
  }
  for (int e = 0; e < m.num_edges(); ++e)
    for (int i = 0; i < 2; ++i)
      x[s.sigma_dof(e, i)] = m.edge_length(e) * kSigma.row(i).dot(m.edge_normal(e));
  return x;
}

using testing::perturbed_square;

std::vector<BoundaryRole> neumann_everywhere(const Mesh& m) {
  return std::vector<BoundaryRole>(m.group_names().size(), {GroupRole::kNeumann});
}

TEST(Exactness, P1ReproducesLinearAndRt0ConstantFields) {
  Mesh m = perturbed_square();
  FoslsSpace<2> s(m, neumann_everywhere(m));
  FeField field(s, interpolate(s), 1.0);
  for (int t = 0; t < m.num_triangles(); ++t) {
    const auto& tri = m.triangle(t);
    for (double a : {0.1, 0.33, 0.6}) {
      Point x = a * m.vertex(tri[0]) + (0.8 - a) * m.vertex(tri[1]) + 0.2 * m.vertex(tri[2]);
      EXPECT_LT((field.u(t, x) - (kShift + kGrad * x)).norm(), 1e-12);
      EXPECT_LT((field.grad_u(t, x) - kGrad).norm(), 1e-12);
      EXPECT_LT((field.sigma(t, x) - kSigma).norm(), 1e-12);
    }
    EXPECT_LT(field.div_sigma(t).norm(), 1e-11);
  }
}

TEST(Exactness, ProlongationOfACoarseInterpolantIsTheFineInterpolant) {
  MeshHierarchy h = build_mesh_hierarchy(perturbed_square(), 2);
  for (int j = 1; j < h.num_levels(); ++j) {
    FoslsSpace<2> coarse(h.meshes[j - 1], neumann_everywhere(h.meshes[j - 1]));
    FoslsSpace<2> fine(h.meshes[j], neumann_everywhere(h.meshes[j]));
    SparseMatrix p = cartesian_prolongation(h.meshes[j - 1], h.meshes[j], h.maps[j]);
    Vector diff = p * interpolate(coarse) - interpolate(fine);
    EXPECT_LT(diff.lpNorm<Eigen::Infinity>(), 1e-12);
  }
}

// The same on a bisection hierarchy: kept edges, halves, and edges inside triangles split into
// two, three and four.
TEST(Exactness, ProlongationOnBisectedMeshesIsExact) {
  Mesh mesh = perturbed_square();
  BisectionState state = longest_edge_state(mesh);
  int kept = 0, split_in_four = 0;
  for (int step = 0; step < 4; ++step) {
    std::vector<int> marked;
    for (int t = 0; t < mesh.num_triangles(); t += 3 + step) marked.push_back(t);
    Bisection b = refine_by_bisection(mesh, state, marked);
    FoslsSpace<2> coarse(mesh, neumann_everywhere(mesh));
    FoslsSpace<2> fine(b.fine, neumann_everywhere(b.fine));
    SparseMatrix p = cartesian_prolongation(mesh, b.fine, b.maps);
    Vector diff = p * interpolate(coarse) - interpolate(fine);
    EXPECT_LT(diff.lpNorm<Eigen::Infinity>(), 1e-12) << "step " << step;
    for (int f = 0; f < b.fine.num_edges(); ++f)
      kept += b.maps.parent_edge[f] >= 0 && b.fine.edge(f)[0] < mesh.num_vertices() &&
              b.fine.edge(f)[1] < mesh.num_vertices();
    std::vector<int> children(mesh.num_triangles(), 0);
    for (int parent : b.maps.triangle_parent) ++children[parent];
    split_in_four += static_cast<int>(std::count(children.begin(), children.end(), 4));
    mesh = std::move(b.fine);
    state = std::move(b.state);
  }
  EXPECT_GT(kept, 0);
  EXPECT_GT(split_in_four, 0);
}

}  // namespace
}  // namespace fosls
