#include "cli/estimate_command.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "case/case_admission.hpp"
#include "cli/case_file.hpp"
#include "cli/exit_codes.hpp"

namespace fosls {

namespace {

int run_estimate(const std::string& path) {
  CaseReadOptions options;
  options.allow_geo_file = true;  // a local file given by the user who runs the program
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
  const Method method = admission.spec->solver.method;
  std::cout << "unknowns: " << admission.estimate->unknowns
            << (admission.estimate->unknowns_exact ? "" : " (estimated before meshing)") << '\n';
  std::cout << "memory:   " << describe(*admission.estimate, method) << '\n';
  for (Method m : {Method::kMmg, Method::kTnnmg, Method::kPdas, Method::kPgs}) {
    const auto e = estimate_resources(admission.estimate->unknowns, true, m);
    std::printf("  %-6s %8.0f MiB\n",
                m == Method::kMmg     ? "mmg"
                : m == Method::kTnnmg ? "tnnmg"
                : m == Method::kPdas  ? "pdas"
                                      : "pgs",
                e.memory_bytes / (1 << 20));
  }
  return kExitOk;
}

}  // namespace

void add_estimate_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "estimate", "Check a case without solving it and print the memory its solve needs");
  auto path = std::make_shared<std::string>();
  cmd->add_option("CASE", *path, "Case JSON file (- reads standard input)")->required();
  cmd->callback([path, &exit_code] { exit_code = run_estimate(*path); });
}

}  // namespace fosls
