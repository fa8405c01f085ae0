// Bad cases given to the real command line program: each must end with a non-zero exit code
// (not a signal) and an error line on stderr that names the field (JSON pointer) and the
// reason. Runs build/bin/fosls-contact.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const std::string kProgram = std::string(FOSLS_BIN_DIR) + "/fosls-contact";

struct ProcessResult {
  bool signaled = false;
  int signal = 0;
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs the program with `args`, stdin from /dev/null, stdout and stderr captured in files
/// (no pipes, so a chatty child cannot block).
ProcessResult run_program(const std::vector<std::string>& args, const fs::path& work) {
  const fs::path out = work / "stdout.txt", err = work / "stderr.txt";
  const pid_t pid = fork();
  if (pid == 0) {
    const int in_fd = open("/dev/null", O_RDONLY);
    const int out_fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in_fd < 0 || out_fd < 0 || err_fd < 0) _exit(125);
    dup2(in_fd, 0);
    dup2(out_fd, 1);
    dup2(err_fd, 2);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(kProgram.c_str()));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(kProgram.c_str(), argv.data());
    _exit(127);
  }
  ProcessResult r;
  if (pid < 0) return r;
  int status = 0;
  waitpid(pid, &status, 0);
  r.signaled = WIFSIGNALED(status);
  if (r.signaled) r.signal = WTERMSIG(status);
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

/// A folder of its own for one test: other checkouts may run this suite at the same time on
/// the same machine, so the name carries the process id.
fs::path work_folder(const std::string& name) {
  return fs::path(::testing::TempDir()) / (name + "_" + std::to_string(getpid()));
}

/// A valid case (the shipped square Signorini problem in small) that each row breaks.
json valid_case() {
  return json::parse(R"({
    "name": "bad_case_base",
    "mesh": {"builtin": "square", "size": 0.5, "refinements": 0},
    "material": {"mu": 1, "lambda": 1},
    "body_force": [0, 0],
    "boundary": {
      "top": {"type": "dirichlet", "displacement": [0, -0.05]},
      "left": {"type": "neumann", "traction": [0, 0]},
      "right": {"type": "neumann", "traction": [0, 0]},
      "bottom": {"type": "contact", "obstacle": {"type": "gap", "g": "0.4*(x-0.5)^2"}}
    },
    "solver": {"method": "mmg", "tolerance": 1e-8, "max_iterations": 50}
  })");
}

const char* kSquareMshTruncated =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n";

struct BadCase {
  std::string name;
  std::function<void(json&)> change;  ///< applied to valid_case(), unless `text` is set
  std::string text;                   ///< the file's exact text (for invalid JSON)
  std::string pointer;                ///< must appear in an `error: <pointer>: ` line
  std::string keyword;                ///< must appear on stderr
  bool no_file = false;               ///< do not write the case file
};

/// Names the row in test output instead of dumping its bytes.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

std::vector<BadCase> bad_cases() {
  auto set = [](std::string pointer, json value) {
    return [pointer, value](json& j) { j[json::json_pointer(pointer)] = value; };
  };
  auto erase = [](std::string parent, std::string key) {
    return [parent, key](json& j) { j[json::json_pointer(parent)].erase(key); };
  };
  const json crossing = json::parse(R"({"size": 0.25, "geometry": {
      "points": [[0, 0], [1, 1], [1, 0], [0, 1]],
      "curves": [{"type": "line", "points": [0, 1]}, {"type": "line", "points": [1, 2]},
                 {"type": "line", "points": [2, 3]}, {"type": "line", "points": [3, 0]}],
      "groups": {"top": [0, 1], "bottom": [2, 3]}}})");
  return {
      {"invalid_json", nullptr, "{\"mesh\": {\"size\": 0.5,}", "", "invalid JSON"},
      {"empty_file", nullptr, " ", "", "invalid JSON"},
      {"number_overflow", nullptr, "{\"mesh\": {\"size\": 1e400}}", "", "overflow"},
      {"not_utf8", nullptr, "{\"name\": \"\xff\xfe\"}", "", "invalid JSON"},
      {"file_missing", nullptr, "", "", "no such file", true},
      {"root_not_object", set("", json::array({1, 2})), "", "/", "JSON object"},
      {"deeply_nested", nullptr, std::string(100000, '[') + std::string(100000, ']'), "/",
       "JSON object"},
      {"missing_mesh", erase("", "mesh"), "", "/mesh", "missing field"},
      {"missing_material", erase("", "material"), "", "/material", "missing field"},
      {"mesh_not_object", set("/mesh", "square"), "", "/mesh", "expected an object"},
      {"two_mesh_sources", set("/mesh/msh", kSquareMshTruncated), "", "/mesh", "exactly one"},
      {"no_mesh_source", erase("/mesh", "builtin"), "", "/mesh", "no mesh source"},
      {"unknown_builtin", set("/mesh/builtin", "circle"), "", "/mesh/builtin", "square, hertz"},
      {"unknown_top_level_key", set("/solvr", json::object()), "", "/solvr", "unknown field"},
      {"unknown_nested_key", set("/mesh/refinement", 2), "", "/mesh/refinement", "unknown field"},
      {"negative_size", set("/mesh/size", -0.5), "", "/mesh/size", "> 0"},
      {"size_as_string", set("/mesh/size", "0.5"), "", "/mesh/size", "expected a number"},
      {"tiny_size", set("/mesh/size", 1e-5), "", "/mesh/size", "coarse triangles"},
      {"too_many_refinements", set("/mesh/refinements", 50), "", "/mesh/refinements", "from 0 to"},
      {"fractional_refinements", set("/mesh/refinements", 1.5), "", "/mesh/refinements", "integer"},
      {"mu_zero", set("/material/mu", 0), "", "/material/mu", "> 0"},
      {"lambda_negative", set("/material/lambda", -1), "", "/material/lambda", "negative"},
      {"lambda_bad_string", set("/material/lambda", "infinite"), "", "/material/lambda", "\"inf\""},
      {"nu_above_half", set("/material", {{"E", 1}, {"nu", 0.6}}), "", "/material/nu", "(-1, 0.5]"},
      {"nu_minus_one", set("/material", {{"E", 1}, {"nu", -1}}), "", "/material/nu", "(-1, 0.5]"},
      {"E_zero", set("/material", {{"E", 0}, {"nu", 0.3}}), "", "/material/E", "> 0"},
      {"both_material_forms", set("/material/E", 1), "", "/material", "not both"},
      {"body_force_one_value", set("/body_force", {1}), "", "/body_force", "array of 2"},
      {"unparsable_expression", set("/boundary/top/displacement/1", "-0.05 *"), "",
       "/boundary/top/displacement/1", "parse"},
      {"unknown_variable", set("/body_force/0", "z*x"), "", "/body_force/0", "unknown variable"},
      {"expression_not_finite", set("/boundary/bottom/obstacle/g", "1/x"), "",
       "/boundary/bottom/obstacle/g", "not finite"},
      {"expression_too_long", set("/body_force/1", "x" + std::string(1100, ' ')), "",
       "/body_force/1", "characters long"},
      {"empty_boundary", set("/boundary", json::object()), "", "/boundary", "non-empty"},
      {"boundary_not_object", set("/boundary", "all"), "", "/boundary", "expected"},
      {"unknown_condition_type", set("/boundary/top/type", "robin"), "", "/boundary/top/type",
       "dirichlet"},
      {"dirichlet_without_displacement", erase("/boundary/top", "displacement"), "",
       "/boundary/top/displacement", "missing field"},
      {"contact_without_obstacle", erase("/boundary/bottom", "obstacle"), "",
       "/boundary/bottom/obstacle", "missing field"},
      {"plane_normal_zero",
       set("/boundary/bottom/obstacle", {{"type", "plane"}, {"point", {0, 0}}, {"normal", {0, 0}}}),
       "", "/boundary/bottom/obstacle/normal", "zero"},
      {"circle_radius_negative",
       set("/boundary/bottom/obstacle", {{"type", "circle"}, {"center", {0, -2}}, {"radius", -1}}),
       "", "/boundary/bottom/obstacle/radius", "> 0"},
      {"obstacle_normal_with_gap", set("/boundary/bottom/direction", "obstacle_normal"), "",
       "/boundary/bottom/direction", "gap"},
      {"group_name_escaped", set("/boundary/a~1b", {{"type", "neumann"}}), "",
       "/boundary/a~1b/traction", "missing field"},
      {"weights_c1_zero", set("/weights", {{"c1", 0}}), "", "/weights/c1", "> 0"},
      {"weights_c3_negative", set("/weights", {{"c3", -0.1}}), "", "/weights/c3", ">= 0"},
      {"unknown_method", set("/solver/method", "cg"), "", "/solver/method", "mmg"},
      {"tolerance_zero", set("/solver/tolerance", 0), "", "/solver/tolerance", "(0, 1)"},
      {"max_iterations_zero", set("/solver/max_iterations", 0), "", "/solver/max_iterations",
       "from 1"},
      {"no_smoothing_for_mmg", set("/solver", {{"pre_smoothing", 0}, {"post_smoothing", 0}}), "",
       "/solver/pre_smoothing", "smoothing"},
      {"name_too_long", set("/name", std::string(300, 'n')), "", "/name", "at most"},
      {"empty_msh", set("/mesh", {{"msh", ""}}), "", "/mesh/msh", "empty"},
      {"msh_not_msh", set("/mesh", {{"msh", "solid cube\nendsolid\n"}}), "", "/mesh/msh",
       "$MeshFormat"},
      {"geo_file_missing", set("/mesh", {{"geo_file", "no_such_mesh.geo"}}), "", "/mesh/geo_file",
       "no such file"},
      {"geometry_not_closed",
       set("/mesh", json::parse(R"({"geometry": {"points": [[0, 0], [1, 0], [0, 1]],
           "curves": [{"type": "line", "points": [0, 1]}, {"type": "line", "points": [1, 2]}],
           "groups": {"top": [0, 1]}}})")),
       "", "/mesh/geometry/points/", "closed loop"},
      // These need the coarse mesh (validate_case and the mesh builders).
      {"corrupt_msh", set("/mesh", {{"msh", kSquareMshTruncated}}), "", "/mesh/msh", "line"},
      {"crossing_segments", set("/mesh", crossing), "", "/mesh/geometry/curves/", "cross"},
      {"unknown_group_in_boundary",
       set("/boundary/sides", {{"type", "neumann"}, {"traction", {0, 0}}}), "", "/boundary/sides",
       "group"},
      // Finite where the reader samples them, but beyond double precision once squared: the
      // solve's numbers stop being numbers, which must not pass as "converged".
      {"displacement_overflows", set("/boundary/top/displacement/1", "-0.05*(1+1e300*(x>0.7))"), "",
       "/", "overflow double precision"},
      {"pressure_overflows", set("/boundary/left", {{"type", "pressure"}, {"pressure", 1e300}}), "",
       "/", "overflow double precision"},
  };
}

class CliBadCase : public ::testing::TestWithParam<BadCase> {};

TEST_P(CliBadCase, FailsWithPointerAndReason) {
  const BadCase& c = GetParam();
  ASSERT_TRUE(fs::exists(kProgram)) << kProgram << " is missing: build the fosls-contact target";
  const fs::path work = work_folder("fosls_cli_bad_" + c.name);
  fs::create_directories(work);
  const fs::path case_path = work / "case.json";
  fs::remove(case_path);
  if (!c.no_file) {
    std::string text = c.text;
    if (c.change) {
      json j = valid_case();
      c.change(j);
      text = j.dump(2);
    }
    std::ofstream(case_path, std::ios::binary) << text;
  }
  const ProcessResult r = run_program({"solve", case_path.string(), "--quiet"}, work);
  EXPECT_FALSE(r.signaled) << "killed by signal " << r.signal << "\n" << r.err;
  EXPECT_NE(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.exit_code, 2) << r.err;  // bad input, not an internal failure
  const std::string prefix =
      c.pointer.empty() ? "error: " + case_path.string() + ": " : "error: " + c.pointer;
  EXPECT_NE(r.err.find(prefix), std::string::npos) << "expected \"" << prefix << "\" in:\n"
                                                   << r.err;
  EXPECT_NE(r.err.find(c.keyword), std::string::npos) << "expected \"" << c.keyword << "\" in:\n"
                                                      << r.err;
  EXPECT_TRUE(r.out.empty()) << "nothing must be solved from a bad case:\n" << r.out.substr(0, 200);
  fs::remove_all(work);
}

INSTANTIATE_TEST_SUITE_P(Table, CliBadCase, ::testing::ValuesIn(bad_cases()),
                         [](const auto& info) { return info.param.name; });

TEST(CliBadCases, TableHasEnoughDistinctCases) { EXPECT_GE(bad_cases().size(), 30u); }

TEST(CliBadCases, EveryErrorIsListedAtOnce) {
  const fs::path work = work_folder("fosls_cli_many_errors");
  fs::create_directories(work);
  json j = valid_case();
  j["mesh"]["size"] = -1;
  j["material"]["mu"] = 0;
  j["solver"]["method"] = "cg";
  std::ofstream(work / "case.json") << j.dump();
  const ProcessResult r = run_program({"solve", (work / "case.json").string()}, work);
  EXPECT_EQ(r.exit_code, 2);
  for (const char* p : {"error: /mesh/size: ", "error: /material/mu: ", "error: /solver/method: "})
    EXPECT_NE(r.err.find(p), std::string::npos) << p << " missing in:\n" << r.err;
  fs::remove_all(work);
}

TEST(CliBadCases, FolderTooLargeFileAndUsageErrors) {
  const fs::path work = work_folder("fosls_cli_files");
  fs::create_directories(work / "folder.json");
  ProcessResult r = run_program({"solve", (work / "folder.json").string()}, work);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("folder"), std::string::npos) << r.err;

  {
    std::ofstream big(work / "big.json");
    big << "{\"name\": \"" << std::string(17u << 20, 'a') << "\"}";
  }
  r = run_program({"solve", (work / "big.json").string()}, work);
  EXPECT_FALSE(r.signaled);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("larger than the limit"), std::string::npos) << r.err;

  // A relative geo_file is looked up next to the case file, not in the working directory.
  json j = valid_case();
  j["mesh"] = {{"geo_file", "meshes/part.geo"}};
  fs::create_directories(work / "cases");
  std::ofstream(work / "cases" / "case.json") << j.dump();
  r = run_program({"solve", (work / "cases" / "case.json").string()}, work);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find((work / "cases" / "meshes" / "part.geo").lexically_normal().string()),
            std::string::npos)
      << r.err;

  // Output paths are checked before solving, so a long solve is not lost to a typo.
  r = run_program({"solve", (work / "cases" / "case.json").string(), "--out",
                   (work / "missing_folder" / "result.json").string()},
                  work);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("error: --out: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  r = run_program({"solve", (work / "cases" / "case.json").string(), "--vtu", work.string()}, work);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is a folder"), std::string::npos) << r.err;

  r = run_program({"solve"}, work);
  EXPECT_EQ(r.exit_code, 2);
  r = run_program({"solve", "x.json", "--no-such-option"}, work);
  EXPECT_EQ(r.exit_code, 2);
  r = run_program({}, work);
  EXPECT_EQ(r.exit_code, 2);
  r = run_program({"example", "no_such_example"}, work);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("signorini_square"), std::string::npos) << r.err;
  fs::remove_all(work);
}

// `solve` ends with the answer: force, peak pressure, contact zone, estimator; not converging
// is a warning with the real numbers and exit code 3.
TEST(CliSolve, SummaryStatesTheAnswerAndNonConvergenceIsAWarning) {
  const fs::path work = work_folder("fosls_cli_summary");
  fs::create_directories(work);
  json j = valid_case();
  j["mesh"]["refinements"] = 2;
  j["solver"]["max_iterations"] = 200;
  std::ofstream(work / "case.json") << j.dump();
  ProcessResult r = run_program(
      {"solve", (work / "case.json").string(), "--out", (work / "result.json").string()}, work);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* line :
       {"converged in ", "force on the body   F = (",
        "peak pressure       p_max = ", "contact zone        ", "error estimator     J^1/2 = "})
    EXPECT_NE(r.err.find(line), std::string::npos) << line << " missing in:\n" << r.err;
  const json result = json::parse(read_file(work / "result.json"));
  const std::string edges = std::to_string(result["contact"]["zone"]["edges"].get<int>()) + " of ";
  EXPECT_NE(r.err.find(edges), std::string::npos) << r.err;

  j["solver"]["max_iterations"] = 2;
  std::ofstream(work / "case.json") << j.dump();
  r = run_program(
      {"solve", (work / "case.json").string(), "--out", (work / "result.json").string()}, work);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("warning: not converged: after 2 iterations"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("NOT converged"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("0.000000"), std::string::npos) << r.err;
  r = run_program(
      {"solve", (work / "case.json").string(), "--quiet", "--out", (work / "result.json").string()},
      work);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("warning: not converged"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("force on the body"), std::string::npos) << r.err;
  fs::remove_all(work);
}

// The shipped examples are embedded in the program and identical to the files.
TEST(CliExamples, ListAndPrintTheShippedFiles) {
  const fs::path work = work_folder("fosls_cli_examples");
  fs::create_directories(work);
  const ProcessResult list = run_program({"example"}, work);
  ASSERT_EQ(list.exit_code, 0) << list.err;
  std::vector<std::string> names;
  std::istringstream lines(list.out);
  for (std::string line; std::getline(lines, line);) names.push_back(line);
  // The 2D examples, then the 3D ones (solver/examples/3d), each name once.
  std::map<std::string, std::string> paths;
  for (const char* folder : {"/solver/examples", "/solver/examples/3d"})
    for (const auto& entry : fs::directory_iterator(std::string(FOSLS_SOURCE_DIR) + folder))
      if (entry.path().extension() == ".json")
        paths[entry.path().stem().string()] = entry.path().string();
  EXPECT_EQ(names.size(), paths.size());
  for (const auto& name : names) {
    const ProcessResult r = run_program({"example", name}, work);
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    ASSERT_TRUE(paths.count(name)) << name;
    std::string file = read_file(paths[name]);
    if (!file.empty() && file.back() != '\n') file += '\n';
    EXPECT_EQ(r.out, file) << name;
  }
  fs::remove_all(work);
}

TEST(CliSolve, MeshesTheGeometryOnce) {
  // A solve meshes its geometry once: the errors that need the coarse mesh come from the run
  // itself (the rows above), not from a separate validation that started gmsh a second time.
  const fs::path work = work_folder("fosls_cli_meshes_once");
  fs::create_directories(work);
  const fs::path count = work / "mesher_runs.txt", script = work / "counting_mesher.sh";
  fs::remove(count);
  const std::string mesher = std::string(FOSLS_BIN_DIR) + "/fosls-mesher";
  std::ofstream(script) << "#!/bin/sh\necho run >> '" << count.string() << "'\nexec '" << mesher
                        << "' \"$@\"\n";
  fs::permissions(script, fs::perms::owner_all);
  json c = valid_case();
  c["mesh"] = json::parse(R"({"geometry": {"points": [[0, 0], [1, 0], [1, 1], [0, 1]],
      "curves": [{"type": "line", "points": [0, 1]}, {"type": "line", "points": [1, 2]},
                 {"type": "line", "points": [2, 3]}, {"type": "line", "points": [3, 0]}],
      "groups": {"bottom": [0], "right": [1], "top": [2], "left": [3]}}, "size": 0.5})");
  const fs::path case_path = work / "case.json";
  std::ofstream(case_path) << c.dump(2);
  ::setenv("FOSLS_MESHER", script.c_str(), 1);
  const ProcessResult r = run_program({"solve", case_path.string(), "--quiet"}, work);
  ::unsetenv("FOSLS_MESHER");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(count), "run\n");
}

}  // namespace
