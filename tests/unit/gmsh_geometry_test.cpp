// Declarative geometries meshed through gmsh: groups, arcs that refinement keeps circular,
// every kind of invalid geometry reported with its pointer, .geo files, and concurrent use.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <thread>

#include "case/run/mesh_factory.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/refinement.hpp"

namespace fosls {
namespace {

using Curve = GeometrySpec::Curve;

Curve line(int a, int b) { return {false, {a, b}, -1}; }
Curve arc(int a, int b, int center) { return {true, {a, b}, center}; }

/// The square [0, 2]² whose right side bulges out as a quarter circle around (1, 1).
GeometrySpec square_with_arc() {
  GeometrySpec g;
  g.points = {Point(0, 0), Point(2, 0), Point(2, 2), Point(0, 2), Point(1, 1)};
  g.curves = {line(0, 1), arc(1, 2, 4), line(2, 3), line(3, 0)};
  g.groups = {{"bottom", {0}}, {"arc", {1}}, {"sides", {2, 3}}};
  return g;
}

const double kArcArea = 4.0 + (std::numbers::pi / 2 - 1.0);  // square + circular segment

double area(const Mesh& m) {
  double a = 0.0;
  for (int t = 0; t < m.num_triangles(); ++t) a += m.triangle_area(t);
  return a;
}

/// All (pointer, detail) pairs of the MeshError thrown by meshing g.
std::vector<MeshProblem> errors_of(const GeometrySpec& g, double size = 0.5) {
  try {
    mesh_from_geometry(g, size);
  } catch (const MeshError& e) {
    return e.problems();
  }
  return {};
}

bool has_pointer(const std::vector<MeshProblem>& errors, const std::string& pointer) {
  return std::any_of(errors.begin(), errors.end(),
                     [&](const MeshProblem& e) { return e.field == pointer; });
}

std::string all_details(const std::vector<MeshProblem>& errors) {
  std::string s;
  for (const auto& e : errors) s += e.field + ": " + e.detail + "\n";
  return s;
}

TEST(GmshGeometry, SquareWithArcMeshesWithItsGroups) {
  const Mesh m = mesh_from_geometry(square_with_arc(), 0.3);
  ASSERT_EQ(m.group_names(), (std::vector<std::string>{"bottom", "arc", "sides"}));
  ASSERT_EQ(m.curves().size(), 1u);
  EXPECT_EQ(m.curves()[0].center, Point(1, 1));
  EXPECT_NEAR(m.curves()[0].radius, std::sqrt(2.0), 1e-15);
  double lengths[3] = {0, 0, 0};
  for (int e = 0; e < m.num_edges(); ++e) {
    const int g = m.edge_group(e);
    if (g < 0) continue;
    lengths[g] += m.edge_length(e);
    EXPECT_EQ(m.edge_curve(e) >= 0, g == 1) << "edge " << e;
    if (g == 1) {
      EXPECT_GE(std::min(m.vertex(m.edge(e)[0]).x(), m.vertex(m.edge(e)[1]).x()), 2.0);
    }
    if (g == 0) {
      EXPECT_EQ(m.edge_midpoint(e).y(), 0.0);
    }
  }
  EXPECT_NEAR(lengths[0], 2.0, 1e-12);
  EXPECT_NEAR(lengths[1], std::sqrt(2.0) * std::numbers::pi / 2, 0.02);
  EXPECT_NEAR(lengths[2], 4.0, 1e-12);
  EXPECT_NEAR(area(m), kArcArea, 0.02);
  const auto [h_min, h_max] = m.edge_length_range();
  EXPECT_GT(h_min, 0.1);
  EXPECT_LT(h_max, 0.5);

  // Refinement converges to the curved domain because new arc vertices sit on the circle.
  const MeshHierarchy h = build_mesh_hierarchy(m, 2);
  for (int e = 0; e < h.finest().num_edges(); ++e) {
    if (h.finest().edge_curve(e) < 0) continue;
    for (int v : h.finest().edge(e))
      EXPECT_NEAR((h.finest().vertex(v) - Point(1, 1)).norm(), std::sqrt(2.0), 1e-12);
  }
  EXPECT_NEAR(area(h.finest()), kArcArea, 1e-3);
}

TEST(GmshGeometry, CurveOrderAndOrientationDoNotMatter) {
  GeometrySpec g = square_with_arc();
  g.curves = {line(3, 2), line(0, 3), arc(2, 1, 4), line(1, 0)};
  g.groups = {{"sides", {0, 1}}, {"arc", {2}}, {"bottom", {3}}};
  const Mesh m = mesh_from_geometry(g, 0.3);
  EXPECT_NEAR(area(m), kArcArea, 0.02);
  EXPECT_EQ(m.group_names()[1], "arc");
}

TEST(GmshGeometry, IsDeterministicAndUsableFromTheFactory) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kGeometry;
  spec.geometry = square_with_arc();
  spec.size = 0.4;
  const Mesh a = build_coarse_mesh(spec), b = mesh_from_geometry(square_with_arc(), 0.4);
  ASSERT_EQ(a.num_vertices(), b.num_vertices());
  for (int v = 0; v < a.num_vertices(); ++v) EXPECT_EQ(a.vertex(v), b.vertex(v));
}

TEST(GmshGeometry, RejectsCrossingSegments) {
  GeometrySpec g;  // a bow tie
  g.points = {Point(0, 0), Point(1, 0), Point(0, 1), Point(1, 1)};
  g.curves = {line(0, 1), line(1, 2), line(2, 3), line(3, 0)};
  g.groups = {{"all", {0, 1, 2, 3}}};
  const auto errors = errors_of(g);
  ASSERT_EQ(errors.size(), 1u) << all_details(errors);
  EXPECT_EQ(errors[0].field, "/geometry/curves/3");
  EXPECT_NE(errors[0].detail.find("crosses or touches curve 1 at (0.5, 0.5)"), std::string::npos)
      << errors[0].detail;
}

TEST(GmshGeometry, RejectsOverlappingSegments) {
  GeometrySpec g;  // A → B → D → C → A where C lies on AB: CA runs back over AB
  g.points = {Point(0, 0), Point(2, 0), Point(1, 0), Point(1, 1)};
  g.curves = {line(0, 1), line(1, 3), line(3, 2), line(2, 0)};
  g.groups = {{"all", {0, 1, 2, 3}}};
  const auto errors = errors_of(g);
  ASSERT_FALSE(errors.empty());
  EXPECT_TRUE(has_pointer(errors, "/geometry/curves/3")) << all_details(errors);
  EXPECT_NE(all_details(errors).find("overlaps curve 0"), std::string::npos);
}

TEST(GmshGeometry, RejectsAnArcCrossingASegment) {
  // The short arc from (2, 0) to (2, 2) around (3, 1) swings left to x = 3 − √2 ≈ 1.59,
  // across the left side x = 1.8.
  GeometrySpec g = square_with_arc();
  g.points = {Point(1.8, 0), Point(2, 0), Point(2, 2), Point(1.8, 2), Point(3, 1)};
  const auto errors = errors_of(g, 0.1);
  ASSERT_FALSE(errors.empty());
  EXPECT_TRUE(has_pointer(errors, "/geometry/curves/3")) << all_details(errors);
}

TEST(GmshGeometry, RejectsArcsOnOneCircleThatOverlap) {
  // Unit circle: arc 0 from 0° to 90°, arc 1 from 90° back to 45°, a line closes the loop.
  GeometrySpec g;
  g.points = {Point(1, 0), Point(0, 1), Point(std::sqrt(0.5), std::sqrt(0.5)), Point(0, 0)};
  g.curves = {arc(0, 1, 3), arc(1, 2, 3), line(2, 0)};
  g.groups = {{"all", {0, 1, 2}}};
  const auto errors = errors_of(g);
  EXPECT_TRUE(has_pointer(errors, "/geometry/curves/1")) << all_details(errors);
  EXPECT_NE(all_details(errors).find("overlaps curve 0"), std::string::npos);
}

TEST(GmshGeometry, RejectsLoopsThatDoNotClose) {
  GeometrySpec g = square_with_arc();
  g.curves.pop_back();  // left side missing: points 3 and 0 end one curve each
  g.groups[2].curves = {2};
  const auto errors = errors_of(g);
  EXPECT_TRUE(has_pointer(errors, "/geometry/points/0")) << all_details(errors);
  EXPECT_TRUE(has_pointer(errors, "/geometry/points/3")) << all_details(errors);
  EXPECT_NE(all_details(errors).find("one closed loop"), std::string::npos);

  GeometrySpec two;  // two separate triangles
  two.points = {Point(0, 0), Point(1, 0), Point(0, 1), Point(5, 0), Point(6, 0), Point(5, 1)};
  two.curves = {line(0, 1), line(1, 2), line(2, 0), line(3, 4), line(4, 5), line(5, 3)};
  two.groups = {{"all", {0, 1, 2, 3, 4, 5}}};
  const auto errors2 = errors_of(two);
  ASSERT_EQ(errors2.size(), 1u) << all_details(errors2);
  EXPECT_EQ(errors2[0].field, "/geometry/curves");

  GeometrySpec twin = square_with_arc();  // a second point at (0, 0) breaks the loop
  twin.points.push_back(Point(0, 0));
  twin.curves[3] = line(3, 5);
  EXPECT_TRUE(has_pointer(errors_of(twin), "/geometry/points/5"));
}

TEST(GmshGeometry, RejectsArcsWithUnequalRadiiOrHalfCircles) {
  GeometrySpec g = square_with_arc();
  g.points[4] = Point(1.2, 1.1);
  auto errors = errors_of(g);
  ASSERT_EQ(errors.size(), 1u) << all_details(errors);
  EXPECT_EQ(errors[0].field, "/geometry/curves/1");
  EXPECT_NE(errors[0].detail.find("must be equal"), std::string::npos);

  g.points[4] = Point(2.0, 1.0);
  errors = errors_of(g);
  ASSERT_EQ(errors.size(), 1u) << all_details(errors);
  EXPECT_EQ(errors[0].field, "/geometry/curves/1");
  EXPECT_NE(errors[0].detail.find("half a circle"), std::string::npos);
}

TEST(GmshGeometry, RejectsCurvesInTwoGroupsOrInNone) {
  GeometrySpec g = square_with_arc();
  g.groups.push_back({"again", {1}});
  auto errors = errors_of(g);
  ASSERT_EQ(errors.size(), 1u) << all_details(errors);
  EXPECT_EQ(errors[0].field, "/geometry/groups/3/curves/0");
  EXPECT_NE(errors[0].detail.find("already in group 'arc'"), std::string::npos);

  g = square_with_arc();
  g.groups[2].curves = {2};
  errors = errors_of(g);
  ASSERT_EQ(errors.size(), 1u) << all_details(errors);
  EXPECT_EQ(errors[0].field, "/geometry/curves/3");
}

TEST(GmshGeometry, ListsEveryProblemAtOnce) {
  GeometrySpec g = square_with_arc();
  g.groups = {{"", {0}}, {"arc", {1, 7}}, {"arc", {2, 3}}};
  g.curves.push_back(line(0, 9));
  g.points[2] = Point(2, std::nan(""));
  const auto errors = errors_of(g);
  for (const char* p :
       {"/geometry/points/2", "/geometry/curves/1/points/1", "/geometry/groups/0/name",
        "/geometry/groups/1/curves/1", "/geometry/groups/2/name", "/geometry/curves/4/points/1",
        "/geometry/curves/4"})
    EXPECT_TRUE(has_pointer(errors, p)) << p << "\n" << all_details(errors);
  EXPECT_FALSE(errors_of(GeometrySpec{}).empty());
}

TEST(GmshGeometry, RefusesSizesThatWouldMakeHugeMeshes) {
  const auto errors = errors_of(square_with_arc(), 1e-4);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].field, "/size");
  EXPECT_EQ(errors_of(square_with_arc(), 0.0).at(0).field, "/size");
  EXPECT_EQ(errors_of(square_with_arc(), std::nan("")).at(0).field, "/size");
}

TEST(GmshGeometry, FourThreadsMeshAtOnce) {
  const Mesh serial = mesh_from_geometry(square_with_arc(), 0.1);
  std::vector<int> vertices(4, -1);
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i)
    threads.emplace_back([i, &vertices] {
      for (int k = 0; k < 3; ++k)
        vertices[i] = mesh_from_geometry(square_with_arc(), 0.1).num_vertices();
    });
  for (auto& t : threads) t.join();
  for (int v : vertices) EXPECT_EQ(v, serial.num_vertices());
}

class GeoFile : public ::testing::Test {
 protected:
  void write(const std::string& text) { std::ofstream(path_) << text; }
  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_ = (std::filesystem::temp_directory_path() /
                       ("fosls_geo_test_" + std::to_string(::getpid()) + ".geo"))
                          .string();
};

TEST_F(GeoFile, PhysicalCurvesBecomeGroupsAndCirclesAreRecognised) {
  write(R"(
    Point(1) = {0, 0, 0};  Point(2) = {2, 0, 0};  Point(3) = {2, 2, 0};
    Point(4) = {0, 2, 0};  Point(5) = {1, 1, 0};
    Line(1) = {1, 2};  Circle(2) = {2, 5, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
    Curve Loop(1) = {1, 2, 3, 4};  Plane Surface(1) = {1};
    Physical Curve("bottom") = {1};
    Physical Curve(7) = {2};
    Physical Curve("sides") = {3, 4};
    Mesh.ElementOrder = 2;
  )");
  const Mesh m = mesh_from_geo_file(path_, 0.3);
  EXPECT_EQ(m.group_names(), (std::vector<std::string>{"bottom", "7", "sides"}));
  ASSERT_EQ(m.curves().size(), 1u);
  EXPECT_NEAR((m.curves()[0].center - Point(1, 1)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(m.curves()[0].radius, std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(area(m), kArcArea, 0.02);
  EXPECT_LT(m.edge_length_range().second, 0.45);
  // Meshing a geometry after the script changed global options still gives first order.
  EXPECT_NEAR(area(mesh_from_geometry(square_with_arc(), 0.3)), kArcArea, 0.02);
}

TEST_F(GeoFile, ReportsMissingFilesScriptErrorsAndMissingGroups) {
  auto pointer_of = [](const std::string& path) {
    try {
      mesh_from_geo_file(path, 0.3);
    } catch (const MeshError& e) {
      return e.problems().at(0).field + ": " + e.problems().at(0).detail;
    }
    return std::string("no error");
  };
  EXPECT_EQ(pointer_of("/nonexistent/dir/x.geo").rfind("/geo_file: cannot read", 0), 0u);
  write("Point(1) = {0, 0, 0;\n");
  EXPECT_EQ(pointer_of(path_).rfind("/geo_file: the .geo script failed", 0), 0u);
  write("Point(1) = {0, 0, 0};\n");
  EXPECT_NE(pointer_of(path_).find("no surface"), std::string::npos);
  write("Point(1) = {0, 0, 0};\nLine(1) = {1, 7};\n");
  EXPECT_NE(pointer_of(path_).find("Unknown control point 7"), std::string::npos);
  write(R"(
    Point(1) = {0, 0, 0};  Point(2) = {1, 0, 0};  Point(3) = {0, 1, 0};
    Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 1};
    Curve Loop(1) = {1, 2, 3};  Plane Surface(1) = {1};
  )");
  EXPECT_NE(pointer_of(path_).find("no physical curves"), std::string::npos);
  write(R"(
    Point(1) = {0, 0, 0};  Point(2) = {1, 0, 0};  Point(3) = {0, 1, 0};
    Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 1};
    Curve Loop(1) = {1, 2, 3};  Plane Surface(1) = {1};
    Physical Curve("base") = {1};
  )");
  const std::string missing = pointer_of(path_);
  EXPECT_EQ(missing.rfind("/geo_file", 0), 0u) << missing;
  EXPECT_NE(missing.find("Physical Curve"), std::string::npos) << missing;
}

}  // namespace
}  // namespace fosls
