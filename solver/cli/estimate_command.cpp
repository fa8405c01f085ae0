#include "cli/estimate_command.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "case/admission/case_admission.hpp"
#include "case/admission/memory_size.hpp"
#include "case/admission/time_estimate.hpp"
#include "case/format/case_reader.hpp"
#include "case/format/solver_methods.hpp"
#include "case/run/case_runner.hpp"
#include "cli/admission_options.hpp"
#include "cli/case_file.hpp"
#include "cli/exit_codes.hpp"

namespace fosls {

namespace {

void print_errors(const std::vector<CaseError>& errors) {
  for (const auto& e : errors)
    std::cerr << "error: " << (e.pointer.empty() ? std::string("/") : e.pointer) << ": " << e.detail
              << '\n';
}

int run_estimate(const std::string& path, const std::string& max_memory) {
  const CaseReadOptions options = command_line_read_options(max_memory);
  CaseFile file = load_case_file(path, options.limits.max_case_bytes);
  if (!file.problem.empty()) {
    std::cerr << "error: " << path << ": " << file.problem << '\n';
    return kExitBadInput;
  }
  const CaseAdmission admission = admit_case(file.json, options);
  print_errors(admission.errors);
  // The same rule as solve's: what it refuses, solve refuses before meshing.
  if (!admission.errors.empty()) return kExitBadInput;
  if (!admission.estimate) {  // a 3D .geo script: counted once gmsh has meshed it
    std::cerr << "error: /mesh/geo_file: a .geo script's size is known once gmsh has meshed it; "
                 "fosls-contact solve checks it then, before refining\n";
    return kExitBadInput;
  }
  const SolverMethod method = admission.spec->solver.method;
  std::cout << "unknowns: " << admission.estimate->unknowns
            << (admission.estimate->unknowns_exact ? "" : " (estimated before meshing)") << '\n';
  std::cout << "memory:   " << describe(*admission.estimate, method) << '\n';
  std::cout << "time:     a rough guide, on two cores like the development machine's "
               "(docs/case-format.md, \"Resources\")\n";
  // An adaptive case is admitted at adaptivity.max_dofs with the hierarchy factor of
  // mmg/tnnmg (docs/case-format.md, "Resources"): every row must use the same rule as the line
  // above, or the mmg row contradicts it.
  const bool adaptive = admission.estimate->limited_by == "/adaptivity/max_dofs";
  if (adaptive)
    std::cout << "          (the time of one solve at max_dofs; an adaptive run solves every one "
                 "of its up to "
              << admission.spec->adaptivity->steps + 1 << " steps)\n";
  if (admission.estimate->limited_by == "/accuracy/max_dofs")
    std::cout << "          (the accuracy loop at accuracy.max_dofs, the largest level it may "
                 "make; it stops earlier once the force is accurate enough)\n";
  const CaseSpec& spec = *admission.spec;
  if (const int solves = most_solves(spec); solves > 1 && !adaptive)
    std::cout << "          (the time of one solve; the run makes " << solves << ", one per "
              << (spec.load_step_points.empty() ? "sweep point" : "load step") << ")\n";
  const ProblemCount count = admission.estimate->count();
  // An adaptive accuracy loop keeps the same bisection hierarchy as an adaptive run.
  const bool bisection = adaptive || (spec.accuracy && spec.accuracy->adaptive);
  for (const MethodInfo& m : solver_methods()) {
    const auto e = bisection ? estimate_adaptive_resources(count.unknowns, count, m.method)
                             : estimate_resources(count, m.method);
    const auto seconds = estimated_seconds(count, m.method);
    const std::string time = seconds ? describe_seconds(*seconds) : "time not estimated";
    std::printf("  %-6s %8.0f MiB  %s\n", m.name, e.memory_bytes / (1 << 20), time.c_str());
  }
  return kExitOk;
}

}  // namespace

void add_estimate_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("estimate",
                                 "Check a case without solving it and print the memory (and "
                                 "roughly the time) its solve needs");
  auto path = std::make_shared<std::string>(), max_memory = std::make_shared<std::string>();
  cmd->add_option("CASE", *path, "Case JSON file (- reads standard input)")->required();
  add_max_memory_option(*cmd, *max_memory);
  cmd->callback([path, max_memory, &exit_code] { exit_code = run_estimate(*path, *max_memory); });
}

}  // namespace fosls
