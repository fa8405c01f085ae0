// The shipped Hertz half disk: groups, grading, triangle quality and arcs that stay circular
// under refinement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "case/format/case_error.hpp"
#include "case/run/mesh_factory.hpp"
#include "mesh/builtin_meshes.hpp"
#include "mesh/refinement.hpp"

namespace fosls {
namespace {

double min_angle_degrees(const Mesh& m) {
  double lo = 180.0;
  for (int t = 0; t < m.num_triangles(); ++t) {
    const auto& tri = m.triangle(t);
    for (int k = 0; k < 3; ++k) {
      const Point a = m.vertex(tri[k]), b = m.vertex(tri[(k + 1) % 3]),
                  c = m.vertex(tri[(k + 2) % 3]);
      const double cosine = (b - a).dot(c - a) / ((b - a).norm() * (c - a).norm());
      lo = std::min(lo, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi);
    }
  }
  return lo;
}

bool has_vertex(const Mesh& m, const Point& p) {
  for (const Point& v : m.vertices())
    if (v == p) return true;
  return false;
}

TEST(HertzMesh, GroupsFollowTheFlatSideAndTheContactZone) {
  const HertzParams p;  // R = 1, contact_fraction = 0.5
  const Mesh m = make_hertz(p);
  ASSERT_EQ(m.group_names(), (std::vector<std::string>{"top", "contact", "free"}));
  const int top = m.group_index("top"), contact = m.group_index("contact");
  const int free = m.group_index("free");
  int counts[3] = {0, 0, 0};
  double contact_length = 0.0, free_length = 0.0;
  for (int e = 0; e < m.num_edges(); ++e) {
    const int g = m.edge_group(e);
    if (g < 0) continue;
    ++counts[g];
    const Point a = m.vertex(m.edge(e)[0]), b = m.vertex(m.edge(e)[1]);
    if (g == top) {
      EXPECT_EQ(a.y(), 1.0);
      EXPECT_EQ(b.y(), 1.0);
      EXPECT_EQ(m.edge_curve(e), -1);
      continue;
    }
    // Arc edges: both ends on the circle, the curve is the circle itself.
    ASSERT_GE(m.edge_curve(e), 0);
    const BoundaryCurve& c = m.curves()[m.edge_curve(e)];
    EXPECT_EQ(c.center, Point(0.0, 1.0));
    EXPECT_EQ(c.radius, 1.0);
    EXPECT_NEAR((a - c.center).norm(), 1.0, 1e-14);
    EXPECT_NEAR((b - c.center).norm(), 1.0, 1e-14);
    if (g == contact) {
      EXPECT_LE(std::max(std::abs(a.x()), std::abs(b.x())), 0.5);
      contact_length += m.edge_length(e);
    } else {
      EXPECT_GE(std::min(std::abs(a.x()), std::abs(b.x())), 0.5);
      free_length += m.edge_length(e);
    }
    // Outward normals of the arc point away from the centre.
    EXPECT_GT(m.edge_normal(e).dot(m.edge_midpoint(e) - c.center), 0.0);
  }
  EXPECT_GT(counts[top], 0);
  EXPECT_GT(counts[contact], 0);
  EXPECT_GT(counts[free], 0);
  // Chord lengths approach the arc lengths π/3 (contact) and 2π/3 (free) from below.
  EXPECT_NEAR(contact_length, std::numbers::pi / 3, 0.01);
  EXPECT_NEAR(free_length, 2 * std::numbers::pi / 3, 0.05);
  EXPECT_TRUE(has_vertex(m, Point(0.0, 0.0)));
  EXPECT_TRUE(has_vertex(m, Point(0.5, 1.0 - std::sqrt(0.75))));
  EXPECT_TRUE(has_vertex(m, Point(-0.5, 1.0 - std::sqrt(0.75))));
}

TEST(HertzMesh, CoarseMeshIsGradedSmallAndWellShaped) {
  const Mesh m = make_hertz({});
  const auto [h_min, h_max] = m.edge_length_range();
  EXPECT_GT(h_max / h_min, 4.0);
  EXPECT_LT(h_max / h_min, 12.0);
  EXPECT_GT(min_angle_degrees(m), 15.0);
  EXPECT_LE(m.num_triangles(), 400);
  EXPECT_GE(m.num_triangles(), 20);
  // Finest near the contact point, coarsest near the far corners.
  double near = 1e9, far = 0.0;
  for (int e = 0; e < m.num_edges(); ++e) {
    const double d = m.edge_midpoint(e).norm();
    if (d < 0.2) near = std::min(near, m.edge_length(e));
    if (d > 1.2) far = std::max(far, m.edge_length(e));
  }
  EXPECT_LT(near, 0.15);
  EXPECT_GT(far, 0.4);
  double area = 0.0;
  for (int t = 0; t < m.num_triangles(); ++t) area += m.triangle_area(t);
  EXPECT_NEAR(area, std::numbers::pi / 2, 0.05);
}

TEST(HertzMesh, IsDeterministic) {
  const Mesh a = make_hertz({}), b = make_hertz({});
  ASSERT_EQ(a.num_vertices(), b.num_vertices());
  ASSERT_EQ(a.num_triangles(), b.num_triangles());
  for (int v = 0; v < a.num_vertices(); ++v) EXPECT_EQ(a.vertex(v), b.vertex(v));
  for (int t = 0; t < a.num_triangles(); ++t) EXPECT_EQ(a.triangle(t), b.triangle(t));
}

TEST(HertzMesh, RefinementKeepsArcVerticesOnTheCircle) {
  const MeshHierarchy h =
      build_mesh_hierarchy(make_hertz({.radius = 2.0, .contact_fraction = 0.3}), 3);
  const Point center(0.0, 2.0);
  for (int level = 0; level < h.num_levels(); ++level) {
    const Mesh& m = h.meshes[level];
    int arc_edges = 0;
    for (int e = 0; e < m.num_edges(); ++e) {
      if (m.edge_curve(e) < 0) continue;
      ++arc_edges;
      for (int v : m.edge(e)) EXPECT_NEAR((m.vertex(v) - center).norm(), 2.0, 1e-12);
      if (m.edge_group(e) == m.group_index("contact")) {
        EXPECT_LE(std::abs(m.edge_midpoint(e).x()), 0.6 + 1e-12);
      }
    }
    EXPECT_GT(arc_edges, 0);
  }
  // The refined boundary converges to the half disk: its area tends to π R² / 2.
  double area = 0.0;
  for (int t = 0; t < h.finest().num_triangles(); ++t) area += h.finest().triangle_area(t);
  EXPECT_NEAR(area, 2 * std::numbers::pi, 1e-3);
}

TEST(HertzMesh, RejectsBadParameters) {
  EXPECT_THROW(make_hertz({.radius = -1.0}), std::invalid_argument);
  EXPECT_THROW(make_hertz({.contact_fraction = 1.0}), std::invalid_argument);
  EXPECT_THROW(make_hertz({.contact_fraction = 0.0}), std::invalid_argument);
  EXPECT_THROW(make_hertz({.size = 0.0}), std::invalid_argument);
  EXPECT_THROW(make_hertz({.grading = 0.5}), std::invalid_argument);
}

TEST(MeshFactory, BuildsBuiltinsAndReportsBadParametersWithPointers) {
  MeshSpec spec;
  spec.builtin = "hertz";
  spec.size = 0.1;
  spec.params = {{"radius", 1.0}, {"contact_fraction", 0.4}, {"grading", 5.0}};
  const Mesh hertz = build_coarse_mesh(spec);
  EXPECT_EQ(hertz.group_index("contact"), 1);

  spec.builtin = "square";
  spec.size = 0.5;
  spec.params = {{"width", 2.0}};
  EXPECT_EQ(build_coarse_mesh(spec).num_triangles(), 16);

  auto pointer_of = [](const MeshSpec& s) {
    try {
      build_coarse_mesh(s);
    } catch (const CaseException& e) {
      return e.errors().at(0).pointer;
    }
    return std::string("no error");
  };
  spec.builtin = "triangle";
  EXPECT_EQ(pointer_of(spec), "/mesh/builtin");
  spec.builtin = "square";
  spec.params = {{"radius", 1.0}};
  EXPECT_EQ(pointer_of(spec), "/mesh/builtin/radius");
  spec.params = {};
  spec.size = 1e-5;  // 2·10¹⁰ triangles: refused before any allocation
  EXPECT_EQ(pointer_of(spec), "/mesh/size");
  spec.builtin = "hertz";
  spec.size = 0.1;
  spec.params = {{"contact_fraction", 2.0}};
  EXPECT_EQ(pointer_of(spec), "/mesh/builtin");
  spec.params = {};
  spec.size = 1e-4;
  EXPECT_EQ(pointer_of(spec), "/mesh/size");
}

}  // namespace
}  // namespace fosls
