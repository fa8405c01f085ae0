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
  void update(const IterationRecord& r) {
    if (!enabled_) return;
    char line[160];
    std::snprintf(line, sizeof line,
                  "\riteration %5d  energy %.6e  kkt residual %.3e  active %d\033[K", r.iteration,
                  r.energy, r.kkt_residual, r.active);
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

/// Reports the outcome and picks the exit code: 0 when converged, 3 when not.
int report(const nlohmann::json& result, const SolveOptions& o) {
  const bool converged = result.value("converged", false);
  const int iterations = result.value("iterations", 0);
  if (!converged) {
    std::cerr << "warning: the solver did not converge in " << iterations
              << " iterations; the result is written anyway\n";
    return kExitNotConverged;
  }
  if (!o.quiet)
    std::cerr << "converged in " << iterations << " iterations (" << result.value("levels", 0)
              << " levels, " << result.value("dofs", 0LL) << " unknowns)\n";
  return kExitOk;
}

int run_solve(const SolveOptions& o) {
  CaseReadOptions read_options;
  read_options.allow_geo_file = true;  // a local file given by the user who runs the program

  if (!output_folder_ok("--out", o.out_path) || !output_folder_ok("--vtu", o.vtu_path))
    return kExitBadInput;
  CaseFile file = load_case_file(o.case_path, read_options.limits.max_case_bytes);
  if (!file.problem.empty()) {
    std::cerr << "error: " << o.case_path << ": " << file.problem << '\n';
    return kExitBadInput;
  }
  ProgressLine progress(!o.quiet && isatty(STDERR_FILENO));
  try {
    const auto errors = validate_case(file.json, read_options);
    if (!errors.empty()) {
      print_errors(errors);
      return kExitBadInput;
    }
    auto read = read_case(file.json, read_options);
    if (!read.spec) {
      print_errors(read.errors);
      return kExitBadInput;
    }

    RunControl control;
    control.want_vtu = !o.vtu_path.empty();
    control.on_iteration = [&progress](const IterationRecord& r) { progress.update(r); };
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
  cmd->add_flag("--quiet,-q", o->quiet, "No progress line and no summary");
  cmd->callback([o, &exit_code] { exit_code = run_solve(*o); });
}

}  // namespace fosls
