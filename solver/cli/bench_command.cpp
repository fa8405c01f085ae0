#include "cli/bench_command.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "case/case_runner.hpp"
#include "case/solver_methods.hpp"
#include "cli/case_file.hpp"
#include "cli/exit_codes.hpp"
#include "cli/shipped_examples.hpp"

namespace fosls {

namespace {

struct BenchOptions {
  std::string case_path;
  std::string levels = "2..4";
  std::string methods = "mmg,pdas";
  std::string smoothers = "patch";
  std::string coarse_obstacles = "a";
  double tolerance = 1e-8;
  int max_iterations = 500;
  std::string json_path;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

/// Runs one configuration in a child process, so that its peak memory is its own; the child
/// writes one JSON line to the pipe.
nlohmann::json run_isolated(const nlohmann::json& case_json) {
  int fd[2];
  if (pipe(fd) != 0) return {{"error", "pipe failed"}};
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    nlohmann::json row;
    try {
      CaseReadResult read = read_case(case_json, {});
      if (!read.errors.empty()) {
        row["error"] = read.errors.front().pointer + ": " + read.errors.front().detail;
      } else {
        RunControl control;
        control.want_vtu = false;
        RunOutput out = run_case(*read.spec, control);
        const auto& r = out.result;
        row = {{"dofs", r["dofs"]},
               {"levels", r["levels"]},
               {"iterations", r["iterations"]},
               {"converged", r["converged"]},
               {"rate", r["asymptotic_rate"]},
               {"setup_s", r["timing"]["mesh_s"].get<double>() +
                               r["timing"]["assembly_s"].get<double>() +
                               r["timing"]["setup_s"].get<double>()},
               {"solve_s",
                r["timing"]["solve_s"].get<double>() - r["timing"]["setup_s"].get<double>()},
               // The physical answer per level, so that a mesh-convergence study is one command.
               {"force", r["contact"]["force"]},
               {"peak_pressure", r["contact"]["zone"]["peak_pressure"]},
               {"contact_width", r["contact"]["zone"]["length"]},
               {"estimator", r["functional"]["estimator"]}};
      }
    } catch (const std::exception& e) {
      row["error"] = e.what();
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    row["peak_mib"] = usage.ru_maxrss / 1024.0;
    const std::string line = row.dump() + "\n";
    if (write(fd[1], line.data(), line.size()) < 0) _exit(1);
    close(fd[1]);
    _exit(0);
  }
  close(fd[1]);
  std::string text;
  char buffer[4096];
  ssize_t n;
  while ((n = read(fd[0], buffer, sizeof buffer)) > 0) text.append(buffer, n);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  nlohmann::json row = nlohmann::json::parse(text, nullptr, false);
  if (row.is_discarded())
    return {{"error", "the run ended abnormally (status " + std::to_string(status) + ")"}};
  return row;
}

/// An error line for every name in `names` that `find` does not know ("" when all are known).
template <class Find>
std::string unknown_name(const std::vector<std::string>& names, Find find, const char* option,
                         const std::vector<std::string>& known) {
  std::string out;
  if (names.empty()) out += std::string("error: ") + option + ": give at least one name\n";
  for (const auto& n : names)
    if (!find(n))
      out += std::string("error: ") + option + ": unknown name \"" + n +
             "\"; known: " + join_words(known, ", ") + "\n";
  return out;
}

int run_bench(const BenchOptions& o) {
  nlohmann::json base;
  bool found = false;
  for (const auto& ex : shipped_examples())
    if (ex.name == o.case_path) {
      base = nlohmann::json::parse(ex.text);
      found = true;
    }
  if (!found) {
    CaseFile file = load_case_file(o.case_path, 16u << 20);
    if (!file.problem.empty()) {
      std::cerr << "error: " << o.case_path << ": " << file.problem << '\n';
      return kExitBadInput;
    }
    base = file.json;
  }
  int first = 0, last = 0;
  if (std::sscanf(o.levels.c_str(), "%d..%d", &first, &last) != 2) {
    if (std::sscanf(o.levels.c_str(), "%d", &first) != 1) {
      std::cerr << "error: --levels: expected A..B, e.g. 2..5\n";
      return kExitBadInput;
    }
    last = first;
  }
  if (first < 1 || last < first || last > 12) {
    std::cerr << "error: --levels: need 1 <= A <= B <= 12\n";
    return kExitBadInput;
  }
  std::printf("%-5s %9s %-6s %-6s %-3s %6s %5s %8s %9s %9s %9s %11s %11s %10s %10s\n", "level",
              "dofs", "method", "smooth", "obs", "iters", "conv", "rate", "setup_s", "solve_s",
              "peak_MiB", "|F|", "p_max", "width", "J^1/2");
  nlohmann::json rows = nlohmann::json::array();
  bool all_ok = true;
  const auto methods = split(o.methods), smoothers = split(o.smoothers),
             obstacles = split(o.coarse_obstacles);
  if (auto bad = unknown_name(methods, find_method, "--methods", method_names()) +
                 unknown_name(smoothers, find_smoother, "--smoothers", smoother_names()) +
                 unknown_name(obstacles, find_coarse_obstacle, "--coarse-obstacles",
                              coarse_obstacle_names());
      !bad.empty()) {
    std::cerr << bad;
    return kExitBadInput;
  }
  for (int level = first; level <= last; ++level)
    for (const auto& method : methods)
      for (const auto& smoother : smoothers)
        for (const auto& obstacle : obstacles) {
          // Options a method does not use give no new row.
          const MethodInfo& info = *find_method(method);
          const bool uses_smoother = uses_option(info, SolverOption::kSmoother);
          const bool uses_obstacle = uses_option(info, SolverOption::kCoarseObstacle);
          if ((!uses_smoother && smoother != smoothers[0]) ||
              (!uses_obstacle && obstacle != obstacles[0]))
            continue;
          nlohmann::json c = base;
          c["mesh"]["refinements"] = level - 1;
          c["solver"]["method"] = method;
          c["solver"]["smoother"] = smoother;
          c["solver"]["coarse_obstacle"] = obstacle;
          c["solver"]["tolerance"] = o.tolerance;
          c["solver"]["max_iterations"] = o.max_iterations;
          nlohmann::json row = run_isolated(c);
          row["level"] = level;
          row["method"] = method;
          row["smoother"] = uses_smoother ? smoother : "-";
          row["coarse_obstacle"] = uses_obstacle ? obstacle : "-";
          if (row.contains("error")) {
            all_ok = false;
            std::printf("%-5d %9s %-6s %-6s %-3s error: %s\n", level, "-", method.c_str(),
                        row["smoother"].get<std::string>().c_str(),
                        row["coarse_obstacle"].get<std::string>().c_str(),
                        row["error"].get<std::string>().c_str());
          } else {
            const double force =
                std::hypot(row["force"][0].get<double>(), row["force"][1].get<double>());
            std::printf(
                "%-5d %9lld %-6s %-6s %-3s %6d %5s %8.4f %9.3f %9.3f %9.1f %11.5g %11.5g %10.4g "
                "%10.3g\n",
                level, row["dofs"].get<long long>(), method.c_str(),
                row["smoother"].get<std::string>().c_str(),
                row["coarse_obstacle"].get<std::string>().c_str(), row["iterations"].get<int>(),
                row["converged"].get<bool>() ? "yes" : "no", row["rate"].get<double>(),
                row["setup_s"].get<double>(), row["solve_s"].get<double>(),
                row["peak_mib"].get<double>(), force, row["peak_pressure"].get<double>(),
                row["contact_width"].get<double>(), row["estimator"].get<double>());
          }
          std::fflush(stdout);
          rows.push_back(row);
        }
  if (!o.json_path.empty()) std::ofstream(o.json_path) << rows.dump(2) << '\n';
  return all_ok ? kExitOk : kExitInternal;
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand(
      "bench", "Solve one case over several levels and methods and print a table");
  cmd->add_option("case", o->case_path, "Case file, or the name of a shipped example")->required();
  cmd->add_option("--levels", o->levels, "Levels A..B (levels = refinements + 1)");
  cmd->add_option("--methods", o->methods, "Comma-separated: " + join_words(method_names(), ", "));
  cmd->add_option("--smoothers", o->smoothers,
                  "Comma-separated: " + join_words(smoother_names(), ", "));
  cmd->add_option("--coarse-obstacles", o->coarse_obstacles,
                  "Comma-separated: " + join_words(coarse_obstacle_names(), ", "));
  cmd->add_option("--tolerance", o->tolerance, "Relative KKT tolerance");
  cmd->add_option("--max-iterations", o->max_iterations, "Iteration cap per run");
  cmd->add_option("--json", o->json_path, "Also write the rows as JSON to this file");
  cmd->callback([o, &exit_code] { exit_code = run_bench(*o); });
}

}  // namespace fosls
