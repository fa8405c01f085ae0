#include "cli/solve_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "case/admission/case_admission.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"
#include "cli/admission_options.hpp"
#include "cli/case_file.hpp"
#include "cli/exit_codes.hpp"
#include "cli/result_summary.hpp"

namespace fosls {

namespace {

struct SolveOptions {
  std::string case_path;
  std::string out_path;
  std::string vtu_path;
  std::string msh_path;  ///< --msh: the coarse mesh from this file instead of the case's source
  std::string vtu_format = "binary";  ///< --vtu-format: binary (base64) or ascii
  std::string max_memory;             ///< --max-memory (cli/admission_options.hpp)
  bool quiet = false;
};

void print_errors(const std::vector<CaseError>& errors) {
  for (const auto& e : errors)
    std::cerr << "error: " << (e.pointer.empty() ? std::string("/") : e.pointer) << ": " << e.detail
              << '\n';
}

/// One progress line on a terminal, rewritten after every iteration.
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  /// An adaptive run's solves each get their own line, headed by the step.
  void start_step(int step, long long dofs) {
    finish();
    step_ = "step " + std::to_string(step) + " (" + std::to_string(dofs) + " unknowns)  ";
  }
  void update(const IterationRecord& r) {
    if (!enabled_) return;
    char line[200];
    std::snprintf(line, sizeof line,
                  "\r%siteration %5d  J %.6e  kkt residual %.3e  active %d\033[K", step_.c_str(),
                  r.iteration, r.energy, r.kkt_residual, r.active);
    std::cerr << line << std::flush;
    shown_ = true;
  }
  void finish() {
    if (shown_) std::cerr << '\n';
    shown_ = false;
  }

 private:
  bool enabled_;
  bool shown_ = false;
  std::string step_;
};

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) {
    std::cerr << "error: cannot write " << path << ": " << std::strerror(errno) << '\n';
    return false;
  }
  out << text;
  out.close();
  if (!out) {
    std::cerr << "error: cannot write " << path << '\n';
    return false;
  }
  return true;
}

/// Checks an output path before solving, so that a long solve is not lost to a typo.
bool output_folder_ok(const std::string& option, const std::string& path) {
  if (path.empty()) return true;
  std::error_code ec;
  const auto folder = std::filesystem::absolute(path, ec).parent_path();
  if (ec || !std::filesystem::is_directory(folder, ec)) {
    std::cerr << "error: " << option << ": the folder " << folder.string() << " does not exist\n";
    return false;
  }
  if (std::filesystem::is_directory(path, ec)) {
    std::cerr << "error: " << option << ": " << path << " is a folder; give a file name\n";
    return false;
  }
  return true;
}

/// Reports the outcome and picks the exit code (result_exit_code). Warnings are printed even
/// with --quiet.
int report(const nlohmann::json& r, const SolveOptions& o) {
  for (const auto& w : r["warnings"]) std::cerr << "warning: " << w.get<std::string>() << '\n';
  if (!o.quiet) {
    const bool solid = r.value("dimension", 2) == 3;
    (solid ? print_result_summary_3d : print_result_summary)(std::cerr, r);
  }
  return result_exit_code(r);
}

/// --msh FILE: the case's mesh source becomes mesh.msh_file (its size and refinements stay).
void use_msh_file(nlohmann::json& case_json, const std::string& path) {
  if (!case_json.is_object()) return;
  auto& mesh = case_json["mesh"];
  if (!mesh.is_object()) mesh = nlohmann::json::object();
  for (const char* source : {"builtin", "geometry", "msh", "msh_file", "geo_file"})
    mesh.erase(source);
  std::error_code ec;
  mesh["msh_file"] = std::filesystem::absolute(path, ec).lexically_normal().string();
}

/// Writes the result JSON (to --out or stdout) and the .vtu (with --vtu); an exit code when
/// something could not be written.
std::optional<int> write_outputs(const nlohmann::json& result, const std::string& vtu,
                                 const SolveOptions& o) {
  const std::string result_text = result.dump(2) + "\n";
  if (o.out_path.empty()) {
    std::cout << result_text << std::flush;
    if (!std::cout) {
      std::cerr << "error: cannot write the result to standard output\n";
      return kExitInternal;
    }
  } else if (!write_file(o.out_path, result_text)) {
    return kExitInternal;
  }
  if (!o.vtu_path.empty() && !write_file(o.vtu_path, vtu)) return kExitInternal;
  return std::nullopt;
}

int run_solve(const SolveOptions& o) {
  const CaseReadOptions read_options = command_line_read_options(o.max_memory);

  if (!output_folder_ok("--out", o.out_path) || !output_folder_ok("--vtu", o.vtu_path))
    return kExitBadInput;
  CaseFile file = load_case_file(o.case_path, read_options.limits.max_case_bytes);
  if (!file.problem.empty()) {
    std::cerr << "error: " << o.case_path << ": " << file.problem << '\n';
    return kExitBadInput;
  }
  if (!o.msh_path.empty()) use_msh_file(file.json, o.msh_path);
  ProgressLine progress(!o.quiet && isatty(STDERR_FILENO));
  try {
    // The admission rule of estimate, bench and the service, without gmsh; what needs the
    // coarse mesh (mesh errors, the exact size) is checked again by run_case once it is built,
    // which throws it as a CaseException (below).
    auto read = admit_case(file.json, read_options);
    if (!read.errors.empty()) {
      print_errors(read.errors);
      return kExitBadInput;
    }

    RunControl control;
    control.want_vtu = !o.vtu_path.empty();
    control.vtu_ascii = o.vtu_format == "ascii";
    control.on_iteration = [&progress](const IterationRecord& r) { progress.update(r); };
    if (read.spec->adaptivity || read.spec->accuracy)
      control.on_step = [&progress](int step, long long dofs) { progress.start_step(step, dofs); };
    RunOutput output = run_case(*read.spec, control, read_options.limits);
    progress.finish();
    if (const auto failed = write_outputs(output.result, output.vtu, o)) return *failed;
    return report(output.result, o);
  } catch (const CaseException& e) {
    progress.finish();
    print_errors(e.errors());
    return kExitBadInput;
  } catch (const TimeLimitReached& e) {
    // The case's own limit, before a first iterate: not converged, and nothing to write.
    progress.finish();
    std::cerr << "error: " << e.what() << '\n';
    return kExitNotConverged;
  } catch (const std::bad_alloc&) {
    // A failed allocation (CHOLMOD's included: solvers/cholmod_checks.hpp) is the machine's
    // limit, not a bug: said as such, so that nobody takes a partial run for an answer.
    progress.finish();
    std::cerr << "error: the solve ran out of memory; a direct factorisation (pdas's, or mmg's "
                 "on its coarsest level) needs the most: use a coarser mesh with more "
                 "refinements, or fewer refinements (fosls-contact estimate tells what a case "
                 "needs)\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    progress.finish();
    std::cerr << "error: " << e.what() << '\n';
    return kExitInternal;
  }
}

}  // namespace

void add_solve_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("solve", "Solve a contact case and write the result JSON");
  auto o = std::make_shared<SolveOptions>();
  cmd->add_option("CASE", o->case_path, "Case JSON file (- reads standard input)")->required();
  cmd->add_option("--out,-o", o->out_path, "Write the result JSON here instead of stdout");
  cmd->add_option("--vtu", o->vtu_path, "Write the solution as a VTK unstructured grid here");
  cmd->add_option("--vtu-format", o->vtu_format,
                  "How the VTU's arrays are written: binary (base64, the default) or ascii")
      ->check(CLI::IsMember({"binary", "ascii"}));
  cmd->add_option("--msh", o->msh_path,
                  "Use this gmsh mesh file (ASCII 4.1) as the coarse mesh instead of the case's "
                  "mesh source");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress line and no summary (warnings still)");
  add_max_memory_option(*cmd, o->max_memory);
  cmd->callback([o, &exit_code] { exit_code = run_solve(*o); });
}

}  // namespace fosls
