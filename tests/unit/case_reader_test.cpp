// Case JSON → CaseSpec (case/format/case_reader.hpp): the shipped examples read, every field lands
// where it belongs, and bad input gets every problem listed with its JSON pointer.

#include "case/format/case_reader.hpp"
#include "../case_errors.hpp"
#include "../shipped_example.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace fosls {
namespace {

using nlohmann::json;
using testing::has_error;

json load_example(const std::string& name) { return testing::load_shipped_example(name); }

/// A small valid case that the tests below break one field at a time.
json valid_case() {
  return json::parse(R"({
    "name": "t",
    "mesh": {"builtin": "square", "size": 0.5, "refinements": 1},
    "material": {"mu": 2, "lambda": 3},
    "boundary": {
      "top": {"type": "dirichlet", "displacement": [0, "-0.01*x"]},
      "bottom": {"type": "contact", "obstacle": {"type": "plane", "point": [0, -0.1],
                                                 "normal": [0, 2]}}
    }
  })");
}

std::string dump_errors(const std::vector<CaseError>& errors) {
  std::string s;
  for (const auto& e : errors) s += "  " + e.pointer + ": " + e.detail + "\n";
  return s;
}

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

TEST(ReadCase, CollectsEveryError) {
  json j = json::parse(R"({
    "name": 5,
    "mesh": {"builtin": "square", "msh": "", "size": -1, "refinements": 99, "extra": true},
    "material": {"mu": 0, "lambda": -2},
    "body_force": [0],
    "boundary": {"top": {"type": "dirichlet", "displacement": [0, "x +* 2"]},
                 "side": {"type": "neumann"},
                 "low": {"type": "contact", "obstacle": {"type": "gap", "g": "q"},
                         "direction": "obstacle_normal"}},
    "weights": {"c1": 0, "c5": 1},
    "solver": {"method": "cg", "tolerance": 0, "max_iterations": 0, "smoother": "jacobi",
               "pre_smoothing": 11, "post_smoothing": -1, "coarse_obstacle": "d"},
    "comment": "unknown"
  })");
  const auto r = read_case(j);
  EXPECT_FALSE(r.spec);
  const std::vector<std::string> pointers = {"/name",
                                             "/mesh",
                                             "/mesh/msh",
                                             "/mesh/size",
                                             "/mesh/refinements",
                                             "/mesh/extra",
                                             "/material/mu",
                                             "/material/lambda",
                                             "/body_force",
                                             "/boundary/top/displacement/1",
                                             "/boundary/side/traction",
                                             "/boundary/low/obstacle/g",
                                             "/weights/c1",
                                             "/weights/c5",
                                             "/solver/method",
                                             "/solver/tolerance",
                                             "/solver/max_iterations",
                                             "/solver/smoother",
                                             "/solver/pre_smoothing",
                                             "/solver/post_smoothing",
                                             "/solver/coarse_obstacle",
                                             "/comment"};
  for (const auto& p : pointers)
    EXPECT_TRUE(has_error(r, p, "")) << p << "\n" << dump_errors(r.errors);
  EXPECT_GE(r.errors.size(), pointers.size());
  for (const auto& e : r.errors) EXPECT_FALSE(e.detail.empty()) << e.pointer;
}

TEST(ReadCase, PointersEscapeTildeAndSlash) {
  json j = valid_case();
  j["boundary"]["a/b~c"] = {{"type", "robin"}};
  j["mesh"]["x/y"] = 1;
  const auto r = read_case(j);
  EXPECT_TRUE(has_error(r, "/boundary/a~1b~0c/type", "dirichlet, neumann, pressure, contact"))
      << dump_errors(r.errors);
  EXPECT_TRUE(has_error(r, "/mesh/x~1y", "unknown field"));
}

TEST(ReadCase, ToleranceDiscretisation) {
  json j = valid_case();
  j["solver"] = {{"tolerance", "discretisation"}, {"discretisation_fraction", 0.25}};
  const auto r = read_case(j);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  EXPECT_EQ(r.spec->solver.stopping, StoppingRule::kDiscretisation);
  EXPECT_EQ(r.spec->solver.discretisation_fraction, 0.25);
  // The KKT test stays, at the default tolerance.
  EXPECT_EQ(r.spec->solver.tolerance, SolverOptions{}.tolerance);
  EXPECT_EQ(read_case(valid_case()).spec->solver.stopping, StoppingRule::kKktResidual);
  for (double f : {0.0, 1.0, -0.1}) {
    j["solver"]["discretisation_fraction"] = f;
    EXPECT_TRUE(has_error(read_case(j), "/solver/discretisation_fraction", "in (0, 1)")) << f;
  }
}

TEST(ReadCase, UnknownFieldsListTheKnownOnes) {
  json j = valid_case();
  j["material"]["Mu"] = 1;
  const auto r = read_case(j);
  ASSERT_TRUE(has_error(r, "/material/Mu", "unknown field")) << dump_errors(r.errors);
  EXPECT_TRUE(has_error(r, "/material/Mu", "expected one of: mu, lambda, E, nu"));
}

TEST(ReadCase, WrongTypesNameTheExpectedType) {
  struct Row {
    const char* pointer;
    json value;
    const char* expected;
  };
  const std::vector<Row> rows = {
      {"/mesh/size", "0.5", "expected a number"},
      {"/mesh/refinements", 1.5, "expected an integer"},
      {"/mesh/builtin", 3, "expected the name of a builtin geometry"},
      {"/material/mu", json::array(), "expected a number"},
      {"/material/lambda", true, "expected a number >= 0 or the string \"inf\""},
      {"/boundary", json::array(), "expected a non-empty object"},
      {"/boundary/top", "dirichlet", "expected an object"},
      {"/boundary/top/displacement", 0, "expected an array of 2"},
      {"/boundary/top/displacement/0", true, "expected a number"},
      {"/solver", "fast", "expected an object"},
      {"/solver/method", 1, "expected a string"},
      {"/weights/c3", "0.5", "expected a number >= 0 or the string \"auto\""},
      {"/solver/tolerance", "tight", "expected the string \"discretisation\""},
      {"/name", json::object(), "expected a string"},
  };
  for (const auto& row : rows) {
    json j = valid_case();
    if (std::string(row.pointer) == "/solver" || std::string(row.pointer) == "/name")
      j[json::json_pointer(row.pointer)] = row.value;
    else if (std::string(row.pointer).starts_with("/solver/"))
      j["solver"][json::json_pointer(row.pointer).back()] = row.value;
    else if (std::string(row.pointer).starts_with("/weights/"))
      j["weights"][json::json_pointer(row.pointer).back()] = row.value;
    else
      j[json::json_pointer(row.pointer)] = row.value;
    const auto r = read_case(j);
    EXPECT_TRUE(has_error(r, row.pointer, row.expected)) << row.pointer << "\n"
                                                         << dump_errors(r.errors);
  }
}

TEST(ReadCase, ValueRanges) {
  struct Row {
    const char* pointer;
    json value;
    const char* word;
  };
  const std::vector<Row> rows = {
      {"/mesh/size", 0, "> 0"},
      {"/mesh/refinements", 9, "from 0 to 8"},
      {"/mesh/refinements", -1, "from 0 to 8"},
      {"/material/mu", -1, "> 0"},
      {"/material/lambda", -0.5, "negative"},
      {"/boundary/bottom/obstacle/normal", json{0, 0}, "zero"},
      {"/boundary/bottom/obstacle/point", json{0, 0, 0}, "array of 2"},
  };
  for (const auto& row : rows) {
    json j = valid_case();
    j[json::json_pointer(row.pointer)] = row.value;
    const auto r = read_case(j);
    EXPECT_TRUE(has_error(r, row.pointer, row.word)) << row.pointer << "\n"
                                                     << dump_errors(r.errors);
  }
  json j = valid_case();
  for (double nu : {-1.0, 0.51, 2.0}) {
    j["material"] = {{"E", 1}, {"nu", nu}};
    EXPECT_TRUE(has_error(read_case(j), "/material/nu", "in (-1, 0.5]")) << nu;
  }
  for (double E : {0.0, -3.0}) {
    j["material"] = {{"E", E}, {"nu", 0.3}};
    EXPECT_TRUE(has_error(read_case(j), "/material/E", "> 0")) << E;
  }
  j["material"] = {{"E", 1}, {"nu", 0.3}, {"mu", 1}};
  EXPECT_TRUE(has_error(read_case(j), "/material", "not both"));
  j["material"] = {{"mu", 1}};
  EXPECT_TRUE(has_error(read_case(j), "/material/lambda", "missing field"));
  j["material"] = json::object();
  EXPECT_TRUE(has_error(read_case(j), "/material", "missing material parameters"));
}

TEST(ReadCase, SolverRules) {
  json j = valid_case();
  j["solver"] = {{"pre_smoothing", 0}, {"post_smoothing", 0}};
  EXPECT_TRUE(has_error(read_case(j), "/solver/pre_smoothing", "mmg"));
  j["solver"]["method"] = "pdas";
  EXPECT_TRUE(read_case(j).spec);
  for (double t : {0.0, 1.0, -1e-3}) {
    j["solver"] = {{"tolerance", t}};
    EXPECT_TRUE(has_error(read_case(j), "/solver/tolerance", "in (0, 1)")) << t;
  }
  j["solver"] = {{"max_iterations", 100001}};
  EXPECT_TRUE(has_error(read_case(j), "/solver/max_iterations", "from 1 to 100000"));
}

TEST(ReadCase, ContactDirectionNeedsAnObstacleNormal) {
  json j = valid_case();
  j["boundary"]["bottom"]["direction"] = "obstacle_normal";
  EXPECT_TRUE(read_case(j).spec);
  j["boundary"]["bottom"]["obstacle"] = {{"type", "gap"}, {"g", 0.1}};
  EXPECT_TRUE(has_error(read_case(j), "/boundary/bottom/direction", "gap"));
  j["boundary"]["bottom"]["direction"] = "sideways";
  EXPECT_TRUE(has_error(read_case(j), "/boundary/bottom/direction", "body_normal"));
  j["boundary"]["bottom"].erase("direction");
  j["boundary"]["bottom"]["obstacle"] = {{"type", "circle"}, {"center", {0, -2}}, {"radius", 0}};
  EXPECT_TRUE(has_error(read_case(j), "/boundary/bottom/obstacle/radius", "> 0"));
  j["boundary"]["bottom"]["obstacle"] = {{"type", "wall"}};
  EXPECT_TRUE(has_error(read_case(j), "/boundary/bottom/obstacle/type", "plane, circle, gap"));
  j["boundary"]["bottom"] = {{"type", "contact"}};
  EXPECT_TRUE(has_error(read_case(j), "/boundary/bottom/obstacle", "missing field"));
}

TEST(ReadCase, MeshSources) {
  json j = valid_case();
  j["mesh"] = {{"size", 0.5}};
  EXPECT_TRUE(has_error(read_case(j), "/mesh", "no mesh source"));
  j["mesh"] = {{"builtin", "square"}, {"msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"}};
  EXPECT_TRUE(has_error(read_case(j), "/mesh", "not builtin and msh"));
  j["mesh"] = {{"builtin", "circle"}};
  EXPECT_TRUE(has_error(read_case(j), "/mesh/builtin", "square, hertz"));
  j["mesh"] = {{"builtin", {{"name", "hertz"}, {"width", 1}}}};
  EXPECT_TRUE(has_error(read_case(j), "/mesh/builtin/width", "unknown field"));
  j["mesh"] = {{"builtin", {{"name", "hertz"}, {"contact_fraction", 1}, {"grading", 0.5}}}};
  auto hertz = read_case(j);
  EXPECT_TRUE(has_error(hertz, "/mesh/builtin/contact_fraction", "in (0, 1)"));
  EXPECT_TRUE(has_error(hertz, "/mesh/builtin/grading", "in [1, 100]"));
  j["mesh"] = {{"builtin", {{"radius", 1}}}};
  EXPECT_TRUE(has_error(read_case(j), "/mesh/builtin/name", "missing field"));
  j["mesh"] = {{"msh", "  \n"}};
  EXPECT_TRUE(has_error(read_case(j), "/mesh/msh", "empty"));
  j["mesh"] = {{"msh", "hello"}};
  EXPECT_TRUE(has_error(read_case(j), "/mesh/msh", "$MeshFormat"));
  const std::string msh = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  j["mesh"] = {{"msh", msh}, {"refinements", 2}};
  const auto r = read_case(j);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  EXPECT_EQ(r.spec->mesh.kind, MeshSpec::Kind::kMsh);
  EXPECT_EQ(r.spec->mesh.msh_text, msh);
}

TEST(ReadCase, GeoFileOnlyFromTheCommandLine) {
  // Named by the process: other checkouts may run this suite at the same time.
  const std::string path =
      ::testing::TempDir() + "case_reader_test_" + std::to_string(getpid()) + ".geo";
  std::ofstream(path) << "Point(1) = {0, 0, 0};\n";
  json j = valid_case();
  j["mesh"] = {{"geo_file", path}};
  auto r = read_case(j);  // default options: the service's
  EXPECT_TRUE(has_error(r, "/mesh/geo_file", "only by the command line")) << dump_errors(r.errors);
  EXPECT_TRUE(has_error(r, "/mesh/geo_file", "shell commands"));

  CaseReadOptions cli;
  cli.allow_local_files = true;
  r = read_case(j, cli);
  ASSERT_TRUE(r.spec) << dump_errors(r.errors);
  EXPECT_EQ(r.spec->mesh.kind, MeshSpec::Kind::kGeoFile);
  EXPECT_EQ(r.spec->mesh.geo_path, path);

  j["mesh"]["geo_file"] = path + ".missing";
  EXPECT_TRUE(has_error(read_case(j, cli), "/mesh/geo_file", "no such file"));
  std::filesystem::remove(path);
}

TEST(ReadCase, Limits) {
  CaseReadOptions options;
  options.limits.max_refinements = 2;
  options.limits.max_name_length = 5;
  options.limits.max_expression_length = 10;
  options.limits.max_text_bytes = 40;
  options.limits.max_geometry_entities = 2;
  json j = valid_case();
  j["name"] = "too long";
  j["mesh"]["refinements"] = 3;
  j["boundary"]["top"]["displacement"][0] = "x + x + x + x";
  j["boundary"]["abcdefg"] = {{"type", "neumann"}, {"traction", {0, 0}}};
  auto r = read_case(j, options);
  EXPECT_TRUE(has_error(r, "/name", "at most 5")) << dump_errors(r.errors);
  EXPECT_TRUE(has_error(r, "/mesh/refinements", "from 0 to 2"));
  EXPECT_TRUE(has_error(r, "/boundary", "at most 2"));
  j["boundary"].erase("bottom");
  r = read_case(j, options);
  EXPECT_TRUE(has_error(r, "/boundary/top/displacement/0", "at most 10")) << dump_errors(r.errors);
  EXPECT_TRUE(has_error(r, "/boundary/abcdefg", "at most 5"));

  j = valid_case();
  j["mesh"] = {{"msh", "$MeshFormat\n" + std::string(100, ' ')}};
  EXPECT_TRUE(has_error(read_case(j, options), "/mesh/msh", "at most 40"));
  j["mesh"] = json::parse(R"({"geometry": {"points": [[0, 0], [1, 0], [0, 1]],
      "curves": [{"type": "line", "points": [0, 1]}], "groups": {"a": [0]}}})");
  EXPECT_TRUE(has_error(read_case(j, options), "/mesh/geometry/points", "at most 2"));

  j = valid_case();
  j["mesh"]["size"] = 1e-4;  // 2·10⁸ coarse triangles
  EXPECT_TRUE(has_error(read_case(j), "/mesh/size", "coarse triangles"));
  j["mesh"]["size"] = 0.01;
  EXPECT_TRUE(read_case(j).spec);
}

// Every field of a case that uses every section, replaced by values of every wrong type: each
// is reported at its pointer (or a field inside it), and nothing crashes (the semantic checks use
// only the fields that passed their own rules).
TEST(ReadCase, EveryFieldWithAWrongValueIsReportedAtItsPointer) {
  json rich = valid_case();
  rich["body_force"] = {"sin(x)", 0};
  rich["weights"] = {{"c1", 1}, {"c3", 0.1}};
  rich["solver"] = {{"method", "mmg"},       {"tolerance", 1e-6},  {"max_iterations", 7},
                    {"smoother", "patch"},   {"pre_smoothing", 1}, {"post_smoothing", 0},
                    {"coarse_obstacle", "b"}};
  rich["boundary"]["left"] = {
      {"type", "contact"},
      {"obstacle", {{"type", "circle"}, {"center", {-2, 0.5}}, {"radius", 1}}},
      {"direction", "obstacle_normal"}};
  rich["boundary"]["right"] = {{"type", "neumann"}, {"traction", {0, "y"}}};
  json geometry_case = rich;
  geometry_case["mesh"] = json::parse(R"({"size": 0.5, "geometry": {
      "points": [[0, 0], [1, 0], [0, 1]],
      "curves": [{"type": "line", "points": [0, 1]},
                 {"type": "arc", "points": [1, 2], "center": 0},
                 {"type": "line", "points": [2, 0]}],
      "groups": {"bottom": [0], "top": [1], "left": [2]}}})");
  geometry_case["boundary"].erase("right");
  const std::vector<json> wrong = {nullptr, "x", json::array(), json::object(), -1, 1e300, true};
  int checked = 0;
  for (const json& base : {rich, geometry_case}) {
    ASSERT_TRUE(read_case(base).spec) << dump_errors(read_case(base).errors);
    const json flat = base.flatten();
    for (const auto& [pointer, value] : flat.items()) {
      for (const json& w : wrong) {
        // Values of the right type may be fine or break a rule elsewhere (a moved point makes
        // an arc's ends unequal); wrong types must be reported here.
        if (w.type() == value.type() || (w.is_number() && value.is_number())) continue;
        json j = base;
        j[json::json_pointer(pointer)] = w;
        const auto r = read_case(j);
        if (r.spec) continue;  // e.g. a name "x" or a coordinate -1 may be fine
        ++checked;
        const bool located = std::any_of(r.errors.begin(), r.errors.end(), [&](const CaseError& e) {
          return pointer.starts_with(e.pointer) || e.pointer.starts_with(pointer);
        });
        EXPECT_TRUE(located) << pointer << " = " << w.dump() << "\n" << dump_errors(r.errors);
      }
    }
  }
  EXPECT_GT(checked, 200);
}

TEST(ReadCase, SemanticRulesUseOnlyValidFields) {
  json j = valid_case();
  j["solver"] = {{"coarse_obstacle", "d"}, {"pre_smoothing", 0}, {"post_smoothing", 0}};
  const auto r = read_case(j);
  EXPECT_TRUE(has_error(r, "/solver/coarse_obstacle", "a, b, c")) << dump_errors(r.errors);
  EXPECT_TRUE(has_error(r, "/solver/pre_smoothing", "mmg"));
}

TEST(ReadCase, UnknownCycleNamesTheChoices) {
  json j = valid_case();
  j["solver"] = {{"cycle", "w"}};
  const auto r = read_case(j);
  EXPECT_TRUE(has_error(r, "/solver/cycle", "W, V, F")) << dump_errors(r.errors);
}

TEST(ReadCase, RootMustBeAnObject) {
  for (const json& j : {json::array(), json(3), json("case"), json(nullptr)}) {
    const auto r = read_case(j);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].pointer, "");
    EXPECT_NE(r.errors[0].detail.find("JSON object"), std::string::npos);
  }
  const auto r = read_case(json::object());
  EXPECT_TRUE(has_error(r, "/mesh", "missing field"));
  EXPECT_TRUE(has_error(r, "/material", "missing field"));
  EXPECT_TRUE(has_error(r, "/boundary", "missing field"));
}

TEST(ReadCase, EmptyBoundaryAndIncompleteConditions) {
  json j = valid_case();
  j["boundary"] = json::object();
  EXPECT_TRUE(has_error(read_case(j), "/boundary", "non-empty"));
  j["boundary"] = {{"top", {{"displacement", {0, 0}}}}};
  EXPECT_TRUE(has_error(read_case(j), "/boundary/top/type", "missing field"));
  j["boundary"] = {{"top", {{"type", "dirichlet"}, {"traction", {0, 0}}}}};
  auto r = read_case(j);
  EXPECT_TRUE(has_error(r, "/boundary/top/displacement", "missing field"));
  EXPECT_TRUE(has_error(r, "/boundary/top/traction", "unknown field"));
  j["boundary"] = {{"", {{"type", "neumann"}, {"traction", {0, 0}}}}};
  EXPECT_TRUE(has_error(read_case(j), "/boundary/", "empty"));
}

}  // namespace
}  // namespace fosls
