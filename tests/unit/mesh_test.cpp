// Topology, orientation and refinement of meshes.
#include <gtest/gtest.h>

#include "mesh/builtin_meshes.hpp"
#include "mesh/group_name_index.hpp"
#include "mesh/refinement.hpp"

namespace fosls {
namespace {

TEST(Mesh, SquareTopologyAndOutwardBoundaryNormals) {
  Mesh m = make_square({.size = 0.5});
  EXPECT_EQ(m.num_vertices(), 9);
  EXPECT_EQ(m.num_triangles(), 8);
  EXPECT_EQ(m.num_edges(), 16);
  for (int e = 0; e < m.num_edges(); ++e) {
    if (!m.is_boundary_edge(e)) continue;
    Point mid = m.edge_midpoint(e);
    Point outward = mid - Point(0.5, 0.5);
    EXPECT_GT(m.edge_normal(e).dot(outward), 0.0) << "edge " << e;
  }
}

TEST(Mesh, TriangleEdgeSignsMatchLocalOutwardNormals) {
  Mesh m = make_square({.size = 0.25});
  for (int t = 0; t < m.num_triangles(); ++t) {
    const auto& tri = m.triangle(t);
    Point c = (m.vertex(tri[0]) + m.vertex(tri[1]) + m.vertex(tri[2])) / 3.0;
    for (int k = 0; k < 3; ++k) {
      int e = m.triangle_edge(t, k);
      double out = m.edge_normal(e).dot(m.edge_midpoint(e) - c);
      EXPECT_EQ(out > 0 ? 1 : -1, m.triangle_edge_sign(t, k));
    }
  }
}

TEST(Refinement, RedRefinementQuadruplesAndKeepsGroups) {
  MeshHierarchy h = build_mesh_hierarchy(make_square({.size = 0.5}), 2);
  ASSERT_EQ(h.num_levels(), 3);
  EXPECT_EQ(h.meshes[1].num_triangles(), 32);
  EXPECT_EQ(h.meshes[2].num_triangles(), 128);
  double area = 0;
  for (int t = 0; t < h.finest().num_triangles(); ++t) area += h.finest().triangle_area(t);
  EXPECT_NEAR(area, 1.0, 1e-14);
  int bottom = 0;
  for (int e = 0; e < h.finest().num_edges(); ++e)
    if (h.finest().edge_group(e) == 0) ++bottom;
  EXPECT_EQ(bottom, 8);
  const auto& maps = h.maps[2];
  for (int f = 0; f < h.finest().num_edges(); ++f)
    EXPECT_NE(maps.parent_edge[f] >= 0, maps.parent_triangle[f] >= 0);
}

TEST(Mesh, RejectsBoundaryEdgeWithoutGroup) {
  std::vector<Point> v = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_THROW(Mesh(v, {{0, 1, 2}}, {{0, 1, 0, -1}}, {"g"}), std::invalid_argument);
}

TEST(GroupNameIndex, FindsTheFirstGroupOfANameAndNothingElse) {
  const std::vector<std::string> names = {"top", "bottom", "", "top", "a b", "bottom2", "Bottom"};
  const GroupNameIndex index(names);
  EXPECT_EQ(index.find(names, "top"), 0);  // the first of two, as a linear search finds it
  EXPECT_EQ(index.find(names, "bottom"), 1);
  EXPECT_EQ(index.find(names, ""), 2);
  EXPECT_EQ(index.find(names, "a b"), 4);
  EXPECT_EQ(index.find(names, "bottom2"), 5);
  EXPECT_EQ(index.find(names, "Bottom"), 6);
  for (const char* absent : {"bot", "bottom ", "topp", "z", "A"})
    EXPECT_EQ(index.find(names, absent), -1) << absent;
  const std::vector<std::string> none;
  EXPECT_EQ(GroupNameIndex(none).find(none, "top"), -1);
}

}  // namespace
}  // namespace fosls
