#include "cli/estimate_command.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "case/case_admission.hpp"
#include "case/solver_methods.hpp"
#include "case/time_estimate.hpp"
#include "cli/case_file.hpp"
#include "cli/exit_codes.hpp"

namespace fosls {

namespace {

int run_estimate(const std::string& path) {
  CaseReadOptions options;
  options.allow_local_files = true;  // a local file given by the user who runs the program
  CaseFile file = load_case_file(path, options.limits.max_case_bytes);
  if (!file.problem.empty()) {
    std::cerr << "error: " << path << ": " << file.problem << '\n';
    return kExitBadInput;
  }
  const CaseAdmission admission = admit_case(file.json, options);
  for (const auto& e : admission.errors)
    std::cerr << "error: " << (e.pointer.empty() ? std::string("/") : e.pointer) << ": " << e.detail
              << '\n';
  if (!admission.errors.empty() || !admission.estimate) return kExitBadInput;
  const SolverMethod method = admission.spec->solver.method;
  std::cout << "unknowns: " << admission.estimate->unknowns
            << (admission.estimate->unknowns_exact ? "" : " (estimated before meshing)") << '\n';
  std::cout << "memory:   " << describe(*admission.estimate, method) << '\n';
  std::cout << "time:     a rough guide, on two cores like the development machine's "
               "(docs/case-format.md, \"Resources\")\n";
  for (const MethodInfo& m : solver_methods()) {
    const auto e = estimate_resources(admission.estimate->unknowns, true, m.method);
    const auto seconds = estimated_seconds(admission.estimate->unknowns, m.method);
    char time[48] = "  time not estimated";
    if (seconds) std::snprintf(time, sizeof time, "  about %.2g s", *seconds);
    std::printf("  %-6s %8.0f MiB%s\n", m.name, e.memory_bytes / (1 << 20), time);
  }
  return kExitOk;
}

}  // namespace

void add_estimate_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("estimate",
                                 "Check a case without solving it and print the memory (and "
                                 "roughly the time) its solve needs");
  auto path = std::make_shared<std::string>();
  cmd->add_option("CASE", *path, "Case JSON file (- reads standard input)")->required();
  cmd->callback([path, &exit_code] { exit_code = run_estimate(*path); });
}

}  // namespace fosls
