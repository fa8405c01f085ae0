// Case JSON → CaseSpec (case/format/case_reader.hpp): the shipped examples and the documented
// cases read, and every field lands where it belongs (bad input: case_reader_errors_test.cpp).

#include "case/format/case_reader.hpp"
#include "../case_errors.hpp"
#include "../shipped_example.hpp"
#include "case_reader_cases.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

// In the test support's namespace: valid_case, dump_errors and has_error without usings.
namespace fosls::testing {
namespace {

using nlohmann::json;

json load_example(const std::string& name) { return load_shipped_example(name); }

TEST(ReadCase, EveryShippedExampleReads) {
  int count = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(FOSLS_SOURCE_DIR) + "/solver/examples")) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    const auto r = read_case(load_example(entry.path().stem().string()));
    EXPECT_TRUE(r.spec.has_value()) << entry.path() << "\n" << dump_errors(r.errors);
    EXPECT_TRUE(r.errors.empty());
    if (r.spec) {
      EXPECT_EQ(r.spec->name, entry.path().stem().string());
    }
  }
  EXPECT_GE(count, 5);
}

// Every complete case shown in docs/case-format.md reads without errors.
TEST(ReadCase, CasesInTheDocumentationRead) {
  std::ifstream in(std::string(FOSLS_SOURCE_DIR) + "/docs/case-format.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  int cases = 0;
  for (std::size_t start = doc.find("```json\n"); start != std::string::npos;
       start = doc.find("```json\n", start + 1)) {
    const std::size_t begin = start + 8, end = doc.find("```", begin);
    ASSERT_NE(end, std::string::npos);
    const std::string block = doc.substr(begin, end - begin);
    if (!block.starts_with("{")) continue;  // a fragment such as "geometry": {...}
    const json j = json::parse(block, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << block;
    // Cases that name local files run in tests/contract/msh_workflow_test.py, beside them.
    if (j["mesh"].contains("msh_file") || j["mesh"].contains("geo_file")) continue;
    ++cases;
    const auto r = read_case(j);
    EXPECT_TRUE(r.spec) << j["name"] << "\n" << dump_errors(r.errors);
  }
  EXPECT_GE(cases, 2);
}

TEST(ReadCase, SignoriniSquareExample) {
  const nlohmann::json j = load_example("signorini_square");
  const auto r = read_case(j);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  const CaseSpec& s = *r.spec;
  EXPECT_EQ(s.mesh.kind, MeshSpec::Kind::kBuiltin);
  EXPECT_EQ(s.mesh.builtin, "square");
  EXPECT_EQ(s.mesh.size, j["mesh"]["size"].get<double>());
  EXPECT_EQ(s.mesh.refinements, j["mesh"]["refinements"].get<int>());
  EXPECT_EQ(s.mesh.params.at("width"), 1.0);
  EXPECT_EQ(s.material.mu, 1.0);
  EXPECT_FALSE(s.material.incompressible());
  ASSERT_EQ(s.boundary.size(), 4u);
  const auto& bottom = s.boundary.at("bottom");
  EXPECT_EQ(bottom.type, BoundaryCondition::Type::kContact);
  EXPECT_EQ(bottom.obstacle.kind, Obstacle::Kind::kGap);
  EXPECT_FALSE(bottom.obstacle.gap.is_constant());
  EXPECT_EQ(bottom.direction, ContactDirection::kBodyNormal);
  const auto& top = s.boundary.at("top");
  EXPECT_EQ(top.type, BoundaryCondition::Type::kDirichlet);
  EXPECT_EQ(top.values[1].value, j["boundary"]["top"]["displacement"][1].get<double>());
  EXPECT_TRUE(
      read_case(load_example("signorini_square_incompressible")).spec->material.incompressible());
}

TEST(ReadCase, HertzExample) {
  // The shipped file is tuned by the validation work: compare with what it says, not with
  // numbers copied from it.
  const nlohmann::json j = load_example("hertz");
  const auto r = read_case(j);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  const CaseSpec& s = *r.spec;
  EXPECT_EQ(s.mesh.builtin, "hertz");
  for (const char* p : {"radius", "contact_fraction", "grading"})
    EXPECT_EQ(s.mesh.params.at(p), j["mesh"]["builtin"][p].get<double>()) << p;
  EXPECT_EQ(s.mesh.size, j["mesh"]["size"].get<double>());
  const auto& contact = s.boundary.at("contact");
  EXPECT_EQ(contact.obstacle.kind, Obstacle::Kind::kPlane);
  EXPECT_EQ(contact.obstacle.normal, Point3(0, 1, 0));
  EXPECT_TRUE(read_case(load_example("hertz_incompressible")).spec->material.incompressible());
}

TEST(ReadCase, DefaultsForOptionalFields) {
  const auto r = read_case(valid_case());
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  const CaseSpec& s = *r.spec;
  const Weights w;
  EXPECT_EQ(s.weights.c1, w.c1);
  EXPECT_EQ(s.weights.c3, w.c3);
  EXPECT_EQ(s.solver.method, SolverMethod::kMmg);
  EXPECT_EQ(s.solver.tolerance, SolverOptions{}.tolerance);
  EXPECT_EQ(s.body_force[0].value, 0.0);
  EXPECT_TRUE(s.body_force[1].is_constant());
  EXPECT_EQ(s.boundary.at("top").values[1].expression, "-0.01*x");
  // The plane normal is stored with unit length.
  EXPECT_EQ(s.boundary.at("bottom").obstacle.normal, Point3(0, 1, 0));
  EXPECT_EQ(s.boundary.at("bottom").obstacle.point, Point3(0, -0.1, 0));
}

TEST(ReadCase, EveryFieldIsRead) {
  json j = valid_case();
  j["body_force"] = {"sin(x)", 2};
  j["weights"] = {{"c1", 2}, {"c2", 3}, {"c3", 0}, {"c4", 0.25}, {"c2_volumetric", 2}};
  j["solver"] = {{"method", "pgs"},        {"tolerance", 1e-6},  {"max_iterations", 77},
                 {"smoother", "point"},    {"pre_smoothing", 0}, {"post_smoothing", 0},
                 {"coarse_obstacle", "c"}, {"cycle", "F"}};
  j["mesh"]["builtin"] = {{"name", "square"}, {"x0", -1}, {"width", 2}};
  j["boundary"]["left"] = {{"type", "neumann"}, {"traction", {0.5, "y"}}};
  j["boundary"]["right"] = {
      {"type", "contact"},
      {"obstacle", {{"type", "circle"}, {"center", {3, 0.5}}, {"radius", 1.5}}},
      {"direction", "obstacle_normal"}};
  const auto r = read_case(j);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  const CaseSpec& s = *r.spec;
  EXPECT_EQ(s.body_force[0].expression, "sin(x)");
  EXPECT_EQ(s.body_force[1].value, 2.0);
  EXPECT_EQ(s.weights.c2, 3.0);
  EXPECT_EQ(s.weights.c3, 0.0);
  EXPECT_EQ(s.weights.c4, 0.25);
  EXPECT_EQ(s.weights.c2_volumetric, 2.0);
  EXPECT_EQ(s.solver.method, SolverMethod::kPgs);
  EXPECT_EQ(s.solver.tolerance, 1e-6);
  EXPECT_EQ(s.solver.max_iterations, 77);
  EXPECT_EQ(s.solver.multilevel.smoother, SmootherType::kPoint);
  EXPECT_EQ(s.solver.multilevel.cycle, CycleShape::kF);
  EXPECT_EQ(s.solver.multilevel.pre_smoothing, 0);
  EXPECT_EQ(s.solver.multilevel.projection, CoarseProjection::kC);
  EXPECT_EQ(s.mesh.params.at("x0"), -1.0);
  EXPECT_EQ(s.mesh.params.at("y0"), 0.0);
  EXPECT_EQ(s.mesh.params.at("width"), 2.0);
  EXPECT_EQ(s.boundary.at("left").type, BoundaryCondition::Type::kNeumann);
  EXPECT_EQ(s.boundary.at("left").values[1].expression, "y");
  const auto& right = s.boundary.at("right");
  EXPECT_EQ(right.obstacle.kind, Obstacle::Kind::kBall);
  EXPECT_EQ(right.obstacle.center, Point3(3, 0.5, 0));
  EXPECT_EQ(right.obstacle.radius, 1.5);
  EXPECT_EQ(right.direction, ContactDirection::kObstacleNormal);
}

TEST(ReadCase, YoungsModulusAndPoissonsRatio) {
  json j = valid_case();
  j["material"] = {{"E", 2.6}, {"nu", 0.3}};
  auto r = read_case(j);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  EXPECT_NEAR(r.spec->material.mu, 1.0, 1e-15);
  EXPECT_NEAR(r.spec->material.lambda, 2.6 * 0.3 / (1.3 * 0.4), 1e-14);

  j["material"]["nu"] = 0.5;
  r = read_case(j);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  EXPECT_TRUE(r.spec->material.incompressible());
  EXPECT_NEAR(r.spec->material.mu, 2.6 / 3.0, 1e-15);

  j["material"] = {{"mu", 1}, {"lambda", "inf"}};
  r = read_case(j);
  ASSERT_TRUE(r.spec);
  EXPECT_EQ(r.spec->material.lambda, std::numeric_limits<double>::infinity());
}

TEST(ReadCase, Geometry) {
  json j = valid_case();
  // Quarter disk: two lines and an arc around the origin.
  j["mesh"] = json::parse(R"({"size": 0.2, "geometry": {
      "points": [[0, 0], [1, 0], [0, 1]],
      "curves": [{"type": "line", "points": [0, 1]},
                 {"type": "arc", "points": [1, 2], "center": 0},
                 {"type": "line", "points": [2, 0]}],
      "groups": {"bottom": [0], "top": [1], "left": [2]}}})");
  j["boundary"] = {{"top", {{"type", "dirichlet"}, {"displacement", {0, 0}}}}};
  const auto r = read_case(j);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  const GeometrySpec& g = r.spec->mesh.geometry;
  EXPECT_EQ(r.spec->mesh.kind, MeshSpec::Kind::kGeometry);
  ASSERT_EQ(g.points.size(), 3u);
  EXPECT_EQ(g.points[2], Point(0, 1));
  ASSERT_EQ(g.curves.size(), 3u);
  EXPECT_TRUE(g.curves[1].is_arc);
  EXPECT_EQ(g.curves[1].center, 0);
  EXPECT_EQ(g.curves[1].points[1], 2);
  ASSERT_EQ(g.groups.size(), 3u);
  for (const auto& group : g.groups) {
    ASSERT_EQ(group.curves.size(), 1u);
    if (group.name == "top") {
      EXPECT_EQ(group.curves[0], 1);
    }
  }
}

TEST(ReadCase, GeometryErrors) {
  json j = valid_case();
  j["mesh"] = json::parse(R"({"geometry": {
      "points": [[0, 0], [1, 0], [0, 1], [-1, 0], [5, 5]],
      "curves": [{"type": "line", "points": [0, 1]},
                 {"type": "arc", "points": [1, 3], "center": 0},
                 {"type": "arc", "points": [1, 4], "center": 0},
                 {"type": "line", "points": [2, 9]},
                 {"type": "spline", "points": [2, 0]}],
      "groups": {"a": [0, 1, 0], "b": [1, 7]}}})");
  // The structure first (the mesh layer's geometric checks need a complete geometry) ...
  auto r = read_case(j);
  EXPECT_FALSE(r.spec);
  EXPECT_TRUE(has_error(r, "/mesh/geometry/curves/4/type", "line, arc")) << dump_errors(r.errors);
  // ... then every geometric problem at once, worded and located by the mesh layer's
  // validation (the one that also guards the mesher).
  j["mesh"]["geometry"]["curves"][4]["type"] = "line";
  r = read_case(j);
  EXPECT_TRUE(has_error(r, "/mesh/geometry/curves/1", "half a circle")) << dump_errors(r.errors);
  EXPECT_TRUE(has_error(r, "/mesh/geometry/curves/2", "must be equal"));
  EXPECT_TRUE(has_error(r, "/mesh/geometry/curves/3/points/1", "there are 5 points"));
  EXPECT_TRUE(has_error(r, "/mesh/geometry/groups/b/1", "there are 5 curves"));
  EXPECT_TRUE(has_error(r, "/mesh/geometry/groups/a/2", "already in group 'a'"));
}

TEST(ReadCase, GeometryMustBeOneClosedLoopWithEveryCurveInOneGroup) {
  json j = valid_case();
  j["mesh"] = json::parse(R"({"geometry": {
      "points": [[0, 0], [1, 0], [0, 1], [5, 0], [6, 0], [5, 1]],
      "curves": [{"type": "line", "points": [0, 1]}, {"type": "line", "points": [1, 2]},
                 {"type": "line", "points": [2, 0]}, {"type": "line", "points": [3, 4]},
                 {"type": "line", "points": [4, 5]}, {"type": "line", "points": [5, 3]}],
      "groups": {"a": [0, 1, 2, 3], "b": [3, 4]}}})");
  auto r = read_case(j);
  EXPECT_TRUE(has_error(r, "/mesh/geometry/curves", "several separate loops"))
      << dump_errors(r.errors);
  EXPECT_TRUE(has_error(r, "/mesh/geometry/groups/b/0", "curve 3 is already in group 'a'"));
  EXPECT_TRUE(has_error(r, "/mesh/geometry/curves/5", "in no group"));

  j["mesh"]["geometry"]["curves"].erase(5);
  j["mesh"]["geometry"]["groups"] = {{"a", {0, 1, 2, 3, 4}}};
  r = read_case(j);
  EXPECT_TRUE(has_error(r, "/mesh/geometry/points/3", "point 3 is an end of 1 curves"))
      << dump_errors(r.errors);
}

}  // namespace
}  // namespace fosls::testing
