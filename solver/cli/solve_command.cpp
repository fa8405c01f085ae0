#include "cli/solve_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "case/case_error.hpp"
#include "case/case_reader.hpp"
#include "case/case_runner.hpp"
#include "cli/case_file.hpp"
#include "cli/exit_codes.hpp"

namespace fosls {

namespace {

struct SolveOptions {
  std::string case_path;
  std::string out_path;
  std::string vtu_path;
  std::string msh_path;  ///< --msh: the coarse mesh from this file instead of the case's source
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

std::string g(double v, int digits = 4) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

/// The answer an engineer looks for: force, peak pressure, contact zone, estimator.
void print_summary(const nlohmann::json& r) {
  const auto& c = r["contact"];
  const auto& z = c["zone"];
  std::cerr << "  force on the body   F = (" << g(c["force"][0]) << ", " << g(c["force"][1])
            << ") per unit thickness (the obstacle's force on the body)\n";
  if (c["x"].empty()) {
    std::cerr << "  contact             none: the case has no contact group\n";
  } else if (z["edges"] == 0) {
    std::cerr << "  contact zone        no edge in contact (" << c["x"].size()
              << " contact edges)\n";
  } else {
    std::cerr << "  peak pressure       p_max = " << g(z["peak_pressure"]) << " at ("
              << g(z["peak_location"][0]) << ", " << g(z["peak_location"][1]) << ")\n"
              << "  contact zone        " << z["edges"].get<int>() << " of " << c["x"].size()
              << " contact edges, width " << g(z["length"]) << " (s from " << g(z["s_start"])
              << " to " << g(z["s_end"]) << ")\n";
  }
  std::cerr << "  error estimator     J^1/2 = " << g(r["functional"]["estimator"], 3)
            << " (scaled units)\n";
}

/// One line per point of a sweep: the curve in the terminal.
void print_sweep(const nlohmann::json& sweep) {
  std::cerr << "  sweep of " << sweep["pointer"].get<std::string>() << ":\n"
            << "    value          F_x            F_y            p_max          width          "
               "iterations\n";
  for (const auto& p : sweep["points"]) {
    std::cerr << "    ";
    for (const nlohmann::json& v :
         {p["value"], p["force"][0], p["force"][1], p["peak_pressure"], p["contact_length"]}) {
      const std::string text = g(v);
      std::cerr << text << std::string(text.size() < 15 ? 15 - text.size() : 1, ' ');
    }
    std::cerr << p["iterations"].get<int>()
              << (p["converged"].get<bool>()
                      ? ""
                      : "  NOT converged (" + p["stop_reason"].get<std::string>() + ")")
              << '\n';
  }
}

/// What the summary line adds when the discretisation rule or the rounding level stopped the
/// solve.
std::string stopped_by(const nlohmann::json& r) {
  if (!r.contains("stopping")) return "";
  if (r["stopping"]["converged_by"] == "rounding_level")
    return "; stopped where the residual stalled at its rounding level (see the warning)";
  if (r["stopping"]["converged_by"] != "algebraic_error") return "";
  return "; stopped at the discretisation error: algebraic error " +
         g(r["stopping"]["algebraic_error"], 2) + " <= " + g(r["stopping"]["fraction"], 2) +
         " x J^1/2, J^1/2 = " + g(r["stopping"]["estimator"], 2);
}

/// Reports the outcome and picks the exit code: 0 when converged, 3 when not. Warnings are
/// printed even with --quiet.
int report(const nlohmann::json& r, const SolveOptions& o) {
  for (const auto& w : r["warnings"]) std::cerr << "warning: " << w.get<std::string>() << '\n';
  const bool converged = r.value("converged", false);
  if (!o.quiet) {
    const std::string what = converged ? "converged in " : "NOT converged: stopped after ";
    std::cerr << what << r["iterations"].get<int>() << " iterations (" << r["levels"].get<int>()
              << " levels, " << r["dofs"].get<long long>() << " unknowns, "
              << g(r["timing"]["total_s"], 3) << " s; relative KKT residual "
              << g(r["relative_kkt_residual"], 2) << ", tolerance " << g(r["tolerance"], 2)
              << stopped_by(r) << ")\n";
    print_summary(r);
    if (r.contains("sweep")) print_sweep(r["sweep"]);
  }
  return converged ? kExitOk : kExitNotConverged;
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

int run_solve(const SolveOptions& o) {
  CaseReadOptions read_options;
  read_options.allow_local_files = true;  // a local file given by the user who runs the program

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
    // What needs the coarse mesh (mesh errors, groups the mesh lacks, DOF limits) is checked
    // by run_case, which throws it as a CaseException (below): validating first meshed the
    // geometry twice, and a gmsh run costs 0.1–0.3 s of the mesher process's start-up alone.
    auto read = read_case(file.json, read_options);
    if (!read.spec) {
      print_errors(read.errors);
      return kExitBadInput;
    }

    RunControl control;
    control.want_vtu = !o.vtu_path.empty();
    control.on_iteration = [&progress](const IterationRecord& r) { progress.update(r); };
    if (read.spec->adaptivity)
      control.on_step = [&progress](int step, long long dofs) { progress.start_step(step, dofs); };
    RunOutput output = run_case(*read.spec, control, read_options.limits);
    progress.finish();

    const std::string result_text = output.result.dump(2) + "\n";
    if (o.out_path.empty()) {
      std::cout << result_text << std::flush;
      if (!std::cout) {
        std::cerr << "error: cannot write the result to standard output\n";
        return kExitInternal;
      }
    } else if (!write_file(o.out_path, result_text)) {
      return kExitInternal;
    }
    if (!o.vtu_path.empty() && !write_file(o.vtu_path, output.vtu)) return kExitInternal;
    return report(output.result, o);
  } catch (const CaseException& e) {
    progress.finish();
    print_errors(e.errors());
    return kExitBadInput;
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
  cmd->add_option("--msh", o->msh_path,
                  "Use this gmsh mesh file (ASCII 4.1) as the coarse mesh instead of the case's "
                  "mesh source");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress line and no summary (warnings still)");
  cmd->callback([o, &exit_code] { exit_code = run_solve(*o); });
}

}  // namespace fosls
