// Case JSON → CaseSpec (case/format/case_reader.hpp), bad input: every problem listed at its
// JSON pointer with the reason, wrong types and values named, limits kept, nothing crashes.

#include "../case_errors.hpp"
#include "case/format/case_reader.hpp"
#include "case_reader_cases.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

// In the test support's namespace: valid_case, dump_errors and has_error without usings.
namespace fosls::testing {
namespace {

using nlohmann::json;

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
}  // namespace fosls::testing
