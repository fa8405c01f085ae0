// Newest-vertex bisection: conforming, nested, shape regular, groups and curves inherited.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mesh/bisection.hpp"
#include "mesh/builtin_meshes.hpp"
#include "perturbed_square.hpp"

namespace fosls {
namespace {

/// Sorted angles of a triangle (radians).
std::array<double, 3> angles(const Mesh& m, int t) {
  std::array<double, 3> a;
  const auto& tri = m.triangle(t);
  for (int k = 0; k < 3; ++k) {
    const Point u = m.vertex(tri[(k + 1) % 3]) - m.vertex(tri[k]);
    const Point v = m.vertex(tri[(k + 2) % 3]) - m.vertex(tri[k]);
    a[k] = std::acos(std::clamp(u.dot(v) / (u.norm() * v.norm()), -1.0, 1.0));
  }
  std::sort(a.begin(), a.end());
  return a;
}

double min_angle(const Mesh& m) {
  double lo = M_PI;
  for (int t = 0; t < m.num_triangles(); ++t) lo = std::min(lo, angles(m, t)[0]);
  return lo;
}

/// Boundary length of each group.
std::vector<double> group_lengths(const Mesh& m) {
  std::vector<double> len(m.group_names().size(), 0.0);
  for (int e = 0; e < m.num_edges(); ++e)
    if (m.is_boundary_edge(e)) len[m.edge_group(e)] += m.edge_length(e);
  return len;
}

double total_area(const Mesh& m) {
  double a = 0.0;
  for (int t = 0; t < m.num_triangles(); ++t) a += m.triangle_area(t);
  return a;
}

/// Barycentric coordinates of p in triangle t of m.
Eigen::Vector3d barycentric(const Mesh& m, int t, const Point& p) {
  const auto& tri = m.triangle(t);
  const Point a = m.vertex(tri[0]), b = m.vertex(tri[1]), c = m.vertex(tri[2]);
  Eigen::Matrix2d j;
  j.col(0) = b - a;
  j.col(1) = c - a;
  const Eigen::Vector2d l = j.inverse() * (p - a);
  return {1.0 - l[0] - l[1], l[0], l[1]};
}

/// An unstructured mesh whose triangles are not all similar.
Mesh perturbed_square() { return testing::perturbed_square(0.25, 0.06); }

/// Marks the triangles within `radius` of `centre` (by their centroid).
std::vector<int> near(const Mesh& m, const Point& centre, double radius) {
  std::vector<int> marked;
  for (int t = 0; t < m.num_triangles(); ++t) {
    const auto& tri = m.triangle(t);
    const Point c = (m.vertex(tri[0]) + m.vertex(tri[1]) + m.vertex(tri[2])) / 3.0;
    if ((c - centre).norm() < radius) marked.push_back(t);
  }
  return marked;
}

// Each triangle of an unstructured mesh marked alone: it is split, the neighbour across its
// refinement edge too, and the closure spreads further where refinement edges do not match.
TEST(Bisection, OneMarkedTriangleIsSplitAndTheClosureKeepsTheMeshConforming) {
  const Mesh coarse = perturbed_square();
  const BisectionState state = longest_edge_state(coarse);
  int widest = 0;
  for (int marked = 0; marked < coarse.num_triangles(); ++marked) {
    // The Mesh constructor refuses hanging vertices (an interior edge used by one triangle has
    // no boundary group), so construction alone shows conformity; check the counts as well.
    const Bisection b = refine_by_bisection(coarse, state, {marked});
    std::vector<int> children(coarse.num_triangles(), 0);
    for (int p : b.maps.triangle_parent) ++children[p];
    EXPECT_GE(children[marked], 2);
    for (int t : coarse.edge_triangles(coarse.triangle_edge(marked, state.newest[marked])))
      if (t >= 0) EXPECT_GE(children[t], 2);
    widest = std::max(widest, static_cast<int>(std::count_if(children.begin(), children.end(),
                                                             [](int n) { return n > 1; })));
    int boundary_midpoints = 0;
    for (int e : b.maps.midpoint_edge) boundary_midpoints += coarse.is_boundary_edge(e);
    // Each new vertex splits the two triangles at an interior edge, the one at a boundary edge.
    EXPECT_EQ(b.fine.num_triangles() - coarse.num_triangles(),
              2 * static_cast<int>(b.maps.midpoint_edge.size()) - boundary_midpoints);
    EXPECT_NEAR(total_area(b.fine), 1.0, 1e-14);
    for (int f = 0; f < b.fine.num_edges(); ++f)
      EXPECT_NE(b.maps.parent_edge[f] >= 0, b.maps.parent_triangle[f] >= 0) << "edge " << f;
  }
  EXPECT_GE(widest, 3);  // the closure went beyond the pair sharing a refinement edge
}

TEST(Bisection, MarkingEverythingTwiceEqualsOneRedRefinementInSize) {
  const Mesh coarse = make_square({.size = 0.5});
  std::vector<int> all(coarse.num_triangles());
  for (int t = 0; t < coarse.num_triangles(); ++t) all[t] = t;
  Bisection b = refine_by_bisection(coarse, longest_edge_state(coarse), all);
  std::vector<int> all2(b.fine.num_triangles());
  for (int t = 0; t < b.fine.num_triangles(); ++t) all2[t] = t;
  Bisection b2 = refine_by_bisection(b.fine, b.state, all2);
  EXPECT_EQ(b2.fine.num_triangles(), 4 * coarse.num_triangles());
  EXPECT_EQ(b2.fine.num_vertices(), refine_uniformly(coarse).fine.num_vertices());
  for (int g : b2.state.generation) EXPECT_EQ(g, 2);
}

// A sequence of steps refining towards a corner: nested (every fine triangle inside its
// parent), areas by generation, boundary groups kept, angles bounded below, at most four
// similarity classes per coarse triangle.
TEST(Bisection, NestedShapeRegularAndGroupsKeptOverManySteps) {
  Mesh mesh = perturbed_square();
  const double coarse_min_angle = min_angle(mesh);
  const std::vector<double> lengths = group_lengths(mesh);
  BisectionState state = longest_edge_state(mesh);
  // Coarse ancestor of every triangle, followed through the steps.
  const Mesh coarse = mesh;
  std::vector<int> ancestor(mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); ++t) ancestor[t] = t;
  for (int step = 0; step < 14; ++step) {
    Bisection b = refine_by_bisection(mesh, state, near(mesh, Point(0.0, 0.0), 0.3));
    for (int t = 0; t < b.fine.num_triangles(); ++t) {
      const int p = b.maps.triangle_parent[t];
      for (int v : b.fine.triangle(t)) {
        const Eigen::Vector3d l = barycentric(mesh, p, b.fine.vertex(v));
        EXPECT_GE(l.minCoeff(), -1e-12) << "step " << step << " triangle " << t;
      }
      EXPECT_NEAR(
          b.fine.triangle_area(t),
          mesh.triangle_area(p) / std::pow(2.0, b.state.generation[t] - state.generation[p]),
          1e-14);
    }
    std::vector<int> next(b.fine.num_triangles());
    for (int t = 0; t < b.fine.num_triangles(); ++t) next[t] = ancestor[b.maps.triangle_parent[t]];
    ancestor = std::move(next);
    mesh = std::move(b.fine);
    state = std::move(b.state);
  }
  EXPECT_GT(mesh.num_triangles(), 300);
  EXPECT_NEAR(total_area(mesh), 1.0, 1e-13);
  const std::vector<double> after = group_lengths(mesh);
  for (std::size_t g = 0; g < lengths.size(); ++g) EXPECT_NEAR(after[g], lengths[g], 1e-13);
  const auto [h_min, h_max] = mesh.edge_length_range();
  EXPECT_LT(h_min, 0.25 / 64);  // really local: 14 steps near the corner
  EXPECT_GE(min_angle(mesh), 0.5 * coarse_min_angle - 1e-12);
  std::map<int, std::set<std::array<long, 2>>> classes;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto a = angles(mesh, t);
    classes[ancestor[t]].insert({std::lround(a[0] * 1e6), std::lround(a[1] * 1e6)});
  }
  for (const auto& [t, c] : classes) EXPECT_LE(c.size(), 4u) << "coarse triangle " << t;
}

TEST(Bisection, CurvedBoundaryMidpointsLieOnTheArcAndContactEdgesAreInherited) {
  Mesh mesh = make_hertz({.size = 0.2, .grading = 3});
  const int contact = mesh.group_index("contact");
  BisectionState state = longest_edge_state(mesh);
  for (int step = 0; step < 6; ++step) {
    Bisection b = refine_by_bisection(mesh, state, near(mesh, Point(0.0, 0.0), 0.2));
    mesh = std::move(b.fine);
    state = std::move(b.state);
  }
  int contact_edges = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (mesh.edge_curve(e) < 0) continue;
    for (int v : mesh.edge(e)) EXPECT_NEAR((mesh.vertex(v) - Point(0, 1)).norm(), 1.0, 1e-12);
    if (mesh.edge_group(e) == contact) ++contact_edges;
  }
  const auto [h_min, h_max] = mesh.edge_length_range();
  EXPECT_GT(contact_edges, 20);
  EXPECT_LT(h_min, 0.2 / 4);
}

TEST(Bisection, RejectsTrianglesThatDoNotExistAndForeignStates) {
  const Mesh m = make_square({.size = 0.5});
  EXPECT_THROW(refine_by_bisection(m, longest_edge_state(m), {99}), std::invalid_argument);
  EXPECT_THROW(refine_by_bisection(m, BisectionState{}, {0}), std::invalid_argument);
}

}  // namespace
}  // namespace fosls
