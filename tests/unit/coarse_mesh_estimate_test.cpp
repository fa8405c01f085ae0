// The coarse-mesh estimate against the meshes gmsh really makes: boundary edges counted curve by
// curve (a polygon of many sides shorter than the size), grading layers where the domain has
// room for them, and nothing extra where it has none (a zig-zag). The estimate guards memory,
// so it may overshoot; it must not undershoot by much.

#include "mesh/coarse_mesh_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "case/admission/resource_estimate.hpp"
#include "mesh/gmsh_mesh.hpp"

namespace fosls {
namespace {

GeometrySpec polygon(const std::vector<Point>& points) {
  GeometrySpec g;
  g.points = points;
  std::vector<int> all;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    g.curves.push_back({false, {i, (i + 1) % static_cast<int>(points.size())}, -1});
    all.push_back(i);
  }
  g.groups = {{"all", all}};
  return g;
}

/// n points on circles of radius r0 and r1 in turn (a star; a regular polygon when equal).
GeometrySpec star(int n, double r0, double r1) {
  std::vector<Point> points;
  for (int i = 0; i < n; ++i) {
    const double r = i % 2 ? r1 : r0, t = 2 * std::numbers::pi * i / n;
    points.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return polygon(points);
}

/// A rectangle 10 × 1 whose top is a zig-zag of `teeth` teeth 0.2 high.
GeometrySpec zigzag(int teeth) {
  std::vector<Point> points = {Point(0, 0), Point(10, 0)};
  for (int k = 0; k <= teeth; ++k) points.emplace_back(10 - k * 10.0 / teeth, k % 2 ? 1.2 : 1.0);
  return polygon(points);
}

long long estimated_unknowns(const GeometrySpec& g, double size) {
  SizeField field;
  field.size = size;
  const CoarseMeshEstimate e = estimate_coarse_mesh(g, field);
  return estimated_unknowns_after_refinement(e.triangles(), e.boundary_edges, 0);
}

long long real_unknowns(const GeometrySpec& g, double size) {
  const Mesh m = mesh_from_geometry(g, size);
  return unknowns_after_refinement(m.num_triangles(), m.num_edges(), m.num_vertices(), 0);
}

TEST(CoarseMeshEstimate, ManySidesShorterThanTheSizeCountOneEdgeEach) {
  SizeField field;
  field.size = 1;
  // 10 000 sides of 6.3e-4 with size 1: the perimeter over the size is 6 edges, gmsh makes
  // 10 000 (one per curve), and the triangles follow them.
  const CoarseMeshEstimate e = estimate_coarse_mesh(star(10000, 1, 1), field);
  EXPECT_EQ(e.boundary_edges, 10000);
  EXPECT_GT(e.triangles(), 10000);
  // An arc gets at least its share of gmsh's 7 nodes per circle: a half circle 3 segments,
  // its diameter 1, with a size far above both.
  GeometrySpec half;
  half.points = {Point(-1, 0), Point(1, 0), Point(0, 0)};
  half.curves = {{true, {1, 0}, 2}, {false, {0, 1}, -1}};
  half.groups = {{"all", {0, 1}}};
  field.size = 10;
  EXPECT_EQ(estimate_coarse_mesh(half, field).boundary_edges, 3 + 1);
}

TEST(CoarseMeshEstimate, AgreesWithGmshOnShapesThatDriveTheMeshDifferently) {
  struct Shape {
    const char* what;
    GeometrySpec g;
    double size;
  };
  const Shape shapes[] = {
      {"1000-gon, sides 160 times shorter than the size", star(1000, 1, 1), 1.0},
      {"1000-gon, sides 16 times shorter, room to grade", star(1000, 1, 1), 0.1},
      {"200-gon, sides near the size", star(200, 1, 1), 0.02},
      {"star of 1000 points, no room inside", star(1000, 1, 0.9), 1.0},
      {"zig-zag of 300 teeth", zigzag(300), 1.0},
  };
  for (const Shape& s : shapes) {
    const double estimated = estimated_unknowns(s.g, s.size);
    const double real = real_unknowns(s.g, s.size);
    std::printf("%-50s estimated %8.0f real %8.0f (%+.1f %%)\n", s.what, estimated, real,
                100 * (estimated / real - 1));
    EXPECT_GT(estimated, 0.9 * real) << s.what;
    EXPECT_LT(estimated, 1.5 * real) << s.what;
  }
}

}  // namespace
}  // namespace fosls
