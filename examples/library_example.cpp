// The library in a program of its own, the way MFEM's ex1 shows MFEM: read a case, run it,
// print what an engineer asks first. Build it against the target `fosls` (examples/
// CMakeLists.txt), which exposes only the public headers of solver/case/.
//
//   build/bin/library_example [CASE.json]
//
// Without an argument it solves the shipped signorini_square case. The steps are those of
// `fosls-contact solve` (solver/cli/solve_command.cpp) without its options and files:
//   1. parse the case JSON (nlohmann::json);
//   2. read_case: every field checked, all problems at once, each with its JSON pointer;
//   3. run_case: mesh, levels, assembly, solve and the result JSON (docs/result-format.md);
//   4. read the result: contact.force, iterations, converged.
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

int main(int argc, char** argv) {
  const std::string path =
      argc > 1 ? argv[1] : std::string(FOSLS_SOURCE_DIR) + "/solver/examples/signorini_square.json";

  // 1. The case JSON.
  std::ifstream in(path);
  if (!in) {
    std::cerr << "cannot open " << path << '\n';
    return 2;
  }
  nlohmann::json case_json;
  try {
    case_json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    std::cerr << path << ": not JSON: " << e.what() << '\n';
    return 2;
  }

  // 2. Validation: a CaseSpec, or every problem with its JSON pointer.
  fosls::CaseReadOptions options;
  options.allow_local_files = true;  // mesh.msh_file and mesh.geo_file: this user's own files
  const fosls::CaseReadResult read = fosls::read_case(case_json, options);
  if (!read.spec) {
    for (const fosls::CaseError& e : read.errors)
      std::cerr << "error: " << e.pointer << ": " << e.detail << '\n';
    return 2;
  }

  // 3. The solve. Problems that show only with the mesh (a boundary group the mesh lacks,
  // weights that make the matrix indefinite) arrive as CaseException, with pointers too.
  fosls::RunControl control;
  control.want_vtu = false;
  fosls::RunOutput output;
  try {
    output = fosls::run_case(*read.spec, control, options.limits);
  } catch (const fosls::CaseException& e) {
    for (const fosls::CaseError& error : e.errors())
      std::cerr << "error: " << error.pointer << ": " << error.detail << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }

  // 4. The answer: the force of the obstacle on the body per unit thickness, [F_x, F_y].
  const nlohmann::json& r = output.result;
  const double fx = r["contact"]["force"][0].get<double>();
  const double fy = r["contact"]["force"][1].get<double>();
  std::printf("case:       %s\n", path.c_str());
  std::printf("force:      %.17g %.17g\n", fx, fy);
  std::printf("iterations: %d\n", r["iterations"].get<int>());
  std::printf("converged:  %s\n", r["converged"].get<bool>() ? "yes" : "no");
  return r["converged"].get<bool>() ? 0 : 3;
}
