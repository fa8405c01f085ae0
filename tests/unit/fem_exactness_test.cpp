// Exactness of P1, RT0 and the level transfers.
#include <gtest/gtest.h>

#include "fem/fosls_space.hpp"
#include "fem/transfer.hpp"
#include "mesh/builtin_meshes.hpp"
#include "mesh/refinement.hpp"
#include "post/fe_field.hpp"

namespace fosls {
namespace {

const Eigen::Matrix2d kGrad = (Eigen::Matrix2d() << 0.3, -1.2, 0.7, 2.1).finished();
const Eigen::Vector2d kShift(0.4, -0.25);
const Eigen::Matrix2d kSigma = (Eigen::Matrix2d() << 1.5, -0.4, 0.9, -2.2).finished();

/// Interpolant of u(x) = kShift + kGrad x and σ = kSigma (Cartesian, no contact groups).
Vector interpolate(const FoslsSpace& s) {
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

/// The unit square with its interior vertices moved off the grid (an unstructured mesh).
Mesh perturbed_square() {
  Mesh sq = make_square({.size = 0.2});
  std::vector<Point> v = sq.vertices();
  for (std::size_t i = 0; i < v.size(); ++i) {
    Point& p = v[i];
    if (p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 1)
      p += 0.05 * Point(std::sin(7.0 * i), std::cos(3.0 * i));
  }
  std::vector<std::array<int, 3>> tris;
  for (int t = 0; t < sq.num_triangles(); ++t) tris.push_back(sq.triangle(t));
  std::vector<BoundarySegment> segs;
  for (int e = 0; e < sq.num_edges(); ++e)
    if (sq.is_boundary_edge(e))
      segs.push_back({sq.edge(e)[0], sq.edge(e)[1], sq.edge_group(e), -1});
  return Mesh(v, tris, segs, sq.group_names());
}

std::vector<GroupRole> neumann_everywhere(const Mesh& m) {
  return std::vector<GroupRole>(m.group_names().size(), GroupRole::kNeumann);
}

TEST(Exactness, P1ReproducesLinearAndRt0ConstantFields) {
  Mesh m = perturbed_square();
  FoslsSpace s(m, neumann_everywhere(m));
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
    FoslsSpace coarse(h.meshes[j - 1], neumann_everywhere(h.meshes[j - 1]));
    FoslsSpace fine(h.meshes[j], neumann_everywhere(h.meshes[j]));
    SparseMatrix p = cartesian_prolongation(h.meshes[j - 1], h.meshes[j], h.maps[j]);
    Vector diff = p * interpolate(coarse) - interpolate(fine);
    EXPECT_LT(diff.lpNorm<Eigen::Infinity>(), 1e-12);
  }
}

}  // namespace
}  // namespace fosls
