#include "cli/bench_command.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "case/admission/case_admission.hpp"
#include "case/admission/memory_size.hpp"
#include "case/admission/time_estimate.hpp"
#include "case/format/case_reader.hpp"
#include "case/format/solver_methods.hpp"
#include "case/run/case_runner.hpp"
#include "cli/admission_options.hpp"
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
  std::string cycles = "W";
  double tolerance = 1e-8;
  int max_iterations = 500;
  std::string json_path;
  std::string threads;     ///< comma-separated thread counts; empty: the process's default
  std::string max_memory;  ///< --max-memory (cli/admission_options.hpp)
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

/// One solver setting of a bench row; "-" where the method does not use the option.
struct Configuration {
  std::string method, smoother, obstacle, cycle;
};

/// Every combination of the listed settings, without the repeats of a method that ignores an
/// option (pdas has one configuration however many smoothers are listed).
std::vector<Configuration> configurations(const std::vector<std::string>& methods,
                                          const std::vector<std::string>& smoothers,
                                          const std::vector<std::string>& obstacles,
                                          const std::vector<std::string>& cycles) {
  std::vector<Configuration> out;
  for (const auto& method : methods) {
    const MethodInfo& info = *find_method(method);
    auto used = [&info](SolverOption option, const std::vector<std::string>& names) {
      return uses_option(info, option) ? names : std::vector<std::string>{"-"};
    };
    for (const auto& smoother : used(SolverOption::kSmoother, smoothers))
      for (const auto& obstacle : used(SolverOption::kCoarseObstacle, obstacles))
        for (const auto& cycle : used(SolverOption::kCycle, cycles))
          out.push_back({method, smoother, obstacle, cycle});
  }
  return out;
}

/// The settings columns of the tables: method, smoother, coarse obstacle, cycle.
std::string settings_columns(const nlohmann::json& row) {
  char text[64];
  std::snprintf(text, sizeof text, "%-6s %-6s %-3s %-3s", row["method"].get<std::string>().c_str(),
                row["smoother"].get<std::string>().c_str(),
                row["coarse_obstacle"].get<std::string>().c_str(),
                row["cycle"].get<std::string>().c_str());
  return text;
}

}  // namespace
}  // namespace fosls

// OpenBLAS (under CHOLMOD) keeps its own thread count; declared weak so that the bench still
// links where CHOLMOD uses another BLAS.
extern "C" void openblas_set_num_threads(int) __attribute__((weak));

namespace fosls {
namespace {

/// The columns of a row that 2D's and 3D's results share.
nlohmann::json common_row(const nlohmann::json& r, double setup_s, double solve_s) {
  return {{"dofs", r["dofs"]},
          {"levels", r["levels"]},
          {"iterations", r["iterations"]},
          {"converged", r["converged"]},
          {"rate", r["asymptotic_rate"]},
          {"setup_s", setup_s},
          {"solve_s", solve_s},
          {"total_s", r["timing"]["total_s"]},
          {"threads", omp_get_max_threads()},
          // The physical answer per level, so that a mesh-convergence study is one command.
          {"force", r["contact"]["force"]},
          {"estimator", r["functional"]["estimator"]}};
}

/// A run's row of the table: the columns of the result both dimensions have.
nlohmann::json bench_row(const nlohmann::json& case_json) {
  CaseReadResult read = read_case(case_json, {});
  if (!read.errors.empty())
    return {{"error", read.errors.front().pointer + ": " + read.errors.front().detail}};
  RunControl control;
  control.want_vtu = false;
  const nlohmann::json r = run_case(*read.spec, control).result;
  const auto& timing = r["timing"];
  const double setup_s = timing.value("setup_s", 0.0);
  nlohmann::json row =
      common_row(r, timing["mesh_s"].get<double>() + timing["assembly_s"].get<double>() + setup_s,
                 timing["solve_s"].get<double>() - setup_s);
  if (r.contains("memory")) row["memory"] = r["memory"];
  const nlohmann::json& contact = r["contact"];
  row["peak_pressure"] = contact["zone"]["peak_pressure"];
  // The zone's extent: its width along the boundary in 2D, its area in 3D.
  if (r.value("dimension", 2) == 3)
    row["contact_area"] = contact["area"];
  else
    row["contact_width"] = contact["zone"]["width"];
  return row;
}

/// Runs one configuration in a child process, so that its peak memory is its own; the child
/// writes one JSON line to the pipe. `threads` > 0 sets the OpenMP and OpenBLAS thread counts
/// of the child.
nlohmann::json run_isolated(const nlohmann::json& case_json, int threads) {
  int fd[2];
  if (pipe(fd) != 0) return {{"error", "pipe failed"}};
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    if (threads > 0) {
      omp_set_num_threads(threads);
      if (openblas_set_num_threads) openblas_set_num_threads(threads);
    }
    nlohmann::json row;
    try {
      row = bench_row(case_json);
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

/// Adds to every row the ratios of its total time and peak memory to those of the pdas row
/// with the same level and thread count, and prints them as a second table.
void print_against_pdas(nlohmann::json& rows) {
  auto same_run = [](const nlohmann::json& a, const nlohmann::json& b) {
    return a["level"] == b["level"] && a.value("threads", 0) == b.value("threads", 0);
  };
  bool header = false;
  for (auto& row : rows) {
    if (row.contains("error") || row["method"] == "pdas") continue;
    for (const auto& direct : rows) {
      if (direct["method"] != "pdas" || direct.contains("error") || !same_run(row, direct))
        continue;
      row["time_vs_pdas"] = row["total_s"].get<double>() / direct["total_s"].get<double>();
      row["memory_vs_pdas"] = row["peak_mib"].get<double>() / direct["peak_mib"].get<double>();
      if (!header)
        std::printf("\n%-5s %-6s %-6s %-3s %-3s %3s %12s %12s\n", "level", "method", "smooth",
                    "obs", "cyc", "thr", "time/pdas", "memory/pdas");
      header = true;
      std::printf("%-5d %s %3d %12.3f %12.3f\n", row["level"].get<int>(),
                  settings_columns(row).c_str(), row["threads"].get<int>(),
                  row["time_vs_pdas"].get<double>(), row["memory_vs_pdas"].get<double>());
    }
  }
}

/// One run of the bench: its case, and why admission refused it ("" when admitted).
struct BenchRun {
  int level = 0;
  int threads = 0;
  Configuration setting;
  nlohmann::json case_json;
  std::string refusal;
};

/// What admission says of one run: why it is refused, or its memory and time (no time for pgs
/// in 2D, or for a 3D mesh known only once gmsh has made it).
struct RunEstimate {
  std::string refusal;
  double bytes = 0;
  std::optional<double> seconds;
};

RunEstimate estimate_run(const nlohmann::json& case_json, const CaseReadOptions& options) {
  auto refused = [](const std::vector<CaseError>& errors) {
    return RunEstimate{errors.front().pointer + ": " + errors.front().detail, 0, std::nullopt};
  };
  const CaseAdmission admission = admit_case(case_json, options);
  if (!admission.errors.empty()) return refused(admission.errors);
  if (!admission.estimate) return {};  // a 3D .geo script: counted once gmsh has meshed it
  return {"", admission.estimate->memory_bytes,
          estimated_seconds(admission.estimate->count(), admission.spec->solver.method)};
}

/// Admits every run by the rule solve and the service use, before any runs, and says on stderr
/// what the admitted ones will take in all (a level too many can take hours).
void admit_runs(std::vector<BenchRun>& runs, const CaseReadOptions& options) {
  double seconds = 0, peak = 0;
  int admitted = 0, untimed = 0;
  for (BenchRun& run : runs) {
    const RunEstimate estimate = estimate_run(run.case_json, options);
    if (!estimate.refusal.empty()) {
      run.refusal = "refused before running: " + estimate.refusal;
      continue;
    }
    ++admitted;
    peak = std::max(peak, estimate.bytes);
    if (estimate.seconds)
      seconds += *estimate.seconds;
    else
      ++untimed;
  }
  std::cerr << "bench: " << admitted << " of " << runs.size() << " runs admitted, about "
            << describe_seconds(seconds).substr(6) << " in all"
            << (untimed ? " (without " + std::to_string(untimed) + " pgs runs, not estimated)" : "")
            << ", the largest about " << format_bytes(peak) << "\n";
}

/// The case to bench: a shipped example by name, else a case file; nullopt after saying why not.
std::optional<nlohmann::json> bench_case(const std::string& path) {
  for (const auto& examples : {shipped_examples(), shipped_3d_examples()})
    for (const auto& ex : examples)
      if (ex.name == path) return nlohmann::json::parse(ex.text);
  CaseFile file = load_case_file(path, 16u << 20);
  if (!file.problem.empty()) {
    std::cerr << "error: " << path << ": " << file.problem << '\n';
    return std::nullopt;
  }
  return file.json;
}

/// --levels A..B (or A) into first and last; false after saying why not.
bool parse_levels(const std::string& levels, int& first, int& last) {
  if (std::sscanf(levels.c_str(), "%d..%d", &first, &last) != 2) {
    if (std::sscanf(levels.c_str(), "%d", &first) != 1) {
      std::cerr << "error: --levels: expected A..B, e.g. 2..5\n";
      return false;
    }
    last = first;
  }
  if (first < 1 || last < first || last > 12) {
    std::cerr << "error: --levels: need 1 <= A <= B <= 12\n";
    return false;
  }
  return true;
}

/// --threads 1,2 into thread counts ({0}: the process's default); false after saying why not.
bool parse_threads(const std::string& list, std::vector<int>& thread_counts) {
  for (const auto& t : split(list)) {
    int n = 0;
    if (std::sscanf(t.c_str(), "%d", &n) != 1 || n < 1 || n > 256) {
      std::cerr << "error: --threads: expected thread counts like 1,2, got \"" << t << "\"\n";
      return false;
    }
    thread_counts.push_back(n);
  }
  if (thread_counts.empty()) thread_counts.push_back(0);  // the process's default
  return true;
}

/// The runs: every level, thread count and configuration, each its case.
std::vector<BenchRun> bench_runs(const nlohmann::json& base, const BenchOptions& o, int first,
                                 int last, const std::vector<int>& thread_counts,
                                 const std::vector<Configuration>& settings) {
  std::vector<BenchRun> runs;
  for (int level = first; level <= last; ++level)
    for (const int threads : thread_counts)
      for (const Configuration& setting : settings) {
        nlohmann::json c = base;
        // The bench measures the levels it is given: a run to a requested accuracy or an
        // adaptive loop would choose its own (a note on stderr says they were left out).
        c.erase("accuracy");
        c.erase("adaptivity");
        c["mesh"]["refinements"] = level - 1;
        c["solver"]["method"] = setting.method;
        if (setting.smoother != "-") c["solver"]["smoother"] = setting.smoother;
        if (setting.obstacle != "-") c["solver"]["coarse_obstacle"] = setting.obstacle;
        if (setting.cycle != "-") c["solver"]["cycle"] = setting.cycle;
        c["solver"]["tolerance"] = o.tolerance;
        c["solver"]["max_iterations"] = o.max_iterations;
        runs.push_back({level, threads, setting, std::move(c), {}});
      }
  return runs;
}

/// A number of a row printed with `format`, or "-" in its width when the row has none.
std::string cell(const nlohmann::json& value, const char* format, int width) {
  char text[64];
  if (value.is_number())
    std::snprintf(text, sizeof text, format, value.get<double>());
  else
    std::snprintf(text, sizeof text, "%*s", width, "-");
  return text;
}

/// |F| over all its components (two in 2D, three in 3D).
double force_magnitude(const nlohmann::json& force) {
  double sum = 0;
  for (const auto& component : force) sum += component.get<double>() * component.get<double>();
  return std::sqrt(sum);
}

/// One row of the table (an error line for a run that failed or was refused).
void print_row(const nlohmann::json& row) {
  const int level = row["level"].get<int>();
  if (row.contains("error")) {
    std::printf("%-5d %9s %s error: %s\n", level, "-", settings_columns(row).c_str(),
                row["error"].get<std::string>().c_str());
    return;
  }
  const nlohmann::json none;
  const nlohmann::json& memory = row.contains("memory") ? row["memory"] : none;
  auto in_memory = [&](const char* key) { return memory.is_object() ? memory[key] : none; };
  const nlohmann::json& extent =
      row.contains("contact_area") ? row["contact_area"] : row["contact_width"];
  std::printf(
      "%-5d %9lld %s %3d %6d %5s %s %9.3f %9.3f %9.3f %s %s %9.1f %11.5g %11.5g %s %10.3g\n", level,
      row["dofs"].get<long long>(), settings_columns(row).c_str(), row["threads"].get<int>(),
      row["iterations"].get<int>(), row["converged"].get<bool>() ? "yes" : "no",
      cell(row["rate"], "%8.4f", 8).c_str(), row["setup_s"].get<double>(),
      row["solve_s"].get<double>(), row["total_s"].get<double>(),
      cell(in_memory("assembly_mib"), "%9.1f", 9).c_str(),
      cell(in_memory("chain_mib"), "%9.1f", 9).c_str(), row["peak_mib"].get<double>(),
      force_magnitude(row["force"]), row["peak_pressure"].get<double>(),
      cell(extent, "%10.4g", 10).c_str(), row["estimator"].get<double>());
}

int run_bench(const BenchOptions& o) {
  const std::optional<nlohmann::json> base = bench_case(o.case_path);
  if (!base) return kExitBadInput;
  int first = 0, last = 0;
  std::vector<int> thread_counts;
  if (!parse_levels(o.levels, first, last) || !parse_threads(o.threads, thread_counts))
    return kExitBadInput;
  std::printf(
      "%-5s %9s %-6s %-6s %-3s %-3s %3s %6s %5s %8s %9s %9s %9s %9s %9s %9s %11s %11s %10s "
      "%10s\n",
      "level", "dofs", "method", "smooth", "obs", "cyc", "thr", "iters", "conv", "rate", "setup_s",
      "solve_s", "total_s", "asm_MiB", "chain_MiB", "peak_MiB", "|F|", "p_max",
      (case_dimension(*base) == 3) ? "area" : "width", "J^1/2");
  nlohmann::json rows = nlohmann::json::array();
  bool all_ok = true;
  const auto methods = split(o.methods), smoothers = split(o.smoothers),
             obstacles = split(o.coarse_obstacles), cycles = split(o.cycles);
  if (auto bad = unknown_name(methods, find_method, "--methods", method_names()) +
                 unknown_name(smoothers, find_smoother, "--smoothers", smoother_names()) +
                 unknown_name(obstacles, find_coarse_obstacle, "--coarse-obstacles",
                              coarse_obstacle_names()) +
                 unknown_name(cycles, find_cycle, "--cycles", cycle_names());
      !bad.empty()) {
    std::cerr << bad;
    return kExitBadInput;
  }
  const auto settings = configurations(methods, smoothers, obstacles, cycles);
  for (const char* loop : {"accuracy", "adaptivity"})
    if (base->contains(loop))
      std::cerr << "bench: the case's " << loop
                << " section is left out: the bench solves the levels it is given\n";
  std::vector<BenchRun> runs = bench_runs(*base, o, first, last, thread_counts, settings);
  admit_runs(runs, command_line_read_options(o.max_memory));
  for (const BenchRun& run : runs) {
    nlohmann::json row = run.refusal.empty() ? run_isolated(run.case_json, run.threads)
                                             : nlohmann::json{{"error", run.refusal}};
    row["level"] = run.level;
    row["method"] = run.setting.method;
    row["smoother"] = run.setting.smoother;
    row["coarse_obstacle"] = run.setting.obstacle;
    row["cycle"] = run.setting.cycle;
    if (row.contains("error")) all_ok = false;
    print_row(row);
    std::fflush(stdout);
    rows.push_back(row);
  }
  print_against_pdas(rows);
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
  cmd->add_option("--cycles", o->cycles, "Comma-separated: " + join_words(cycle_names(), ", "));
  cmd->add_option("--tolerance", o->tolerance, "Relative KKT tolerance");
  cmd->add_option("--max-iterations", o->max_iterations, "Iteration cap per run");
  cmd->add_option("--json", o->json_path, "Also write the rows as JSON to this file");
  cmd->add_option("--threads", o->threads,
                  "Comma-separated thread counts (OpenMP and OpenBLAS) to run each "
                  "configuration with, e.g. 1,2; default: the environment's");
  add_max_memory_option(*cmd, o->max_memory);
  cmd->callback([o, &exit_code] { exit_code = run_bench(*o); });
}

}  // namespace fosls
