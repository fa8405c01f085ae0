// Benchmark (not a test): the contact force of a case on the order-2 space P2 × RT1
// (docs/method.md §10), solved exactly by the primal–dual active set method (pdas), beside the
// same case's numbers for a lowest-order solve made elsewhere.
//
//   build/bin/fosls-bench-order2 CASE.json [--solver mmg|pdas]
//
// The case's mesh refined mesh.refinements times carries the order-2 space; c3 "auto" takes the
// lowest order's choice on that mesh. mmg (the default) runs on the lowest-order hierarchy with
// the order-2 level on top (assembly/p2_rt1_level.hpp), with the case's solver options; pdas solves
// exactly. Prints one JSON object: unknowns, force, iterations, times.
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "../case_discretization.hpp"
#include "assembly/discretization.hpp"
#include "assembly/p2_rt1_assembler.hpp"
#include "assembly/p2_rt1_level.hpp"
#include "case/format/case_reader.hpp"
#include "solvers/pdas_step.hpp"
#include "solvers/solve_loop.hpp"

namespace {

using namespace fosls;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const bool usage = argc == 2 || (argc == 4 && std::string(argv[2]) == "--solver");
  if (!usage) {
    std::cerr << "usage: fosls-bench-order2 CASE.json [--solver mmg|pdas]\n";
    return 2;
  }
  const std::string method = argc == 4 ? argv[3] : "mmg";
  std::ifstream in(argv[1]);
  CaseReadResult read = read_case(nlohmann::json::parse(in));
  if (!read.errors.empty()) {
    std::cerr << "case errors: " << read.errors.front().pointer << ": "
              << read.errors.front().detail << "\n";
    return 2;
  }
  CaseSpec spec = *read.spec;
  const auto t0 = Clock::now();
  const std::unique_ptr<Discretization<2>> discretization = testing::case_discretization(spec);
  const Discretization<2>& lowest = *discretization;
  const ProblemData<2>& data = lowest.data();
  const P2Rt1Space space(lowest.meshes().finest(), data.boundary_roles());
  const P2Rt1Assembler assembler(space, data);
  const AssembledProblem problem = assembler.assemble_system();
  const double assembly_s = seconds_since(t0);
  const auto t1 = Clock::now();
  Vector x = Vector::Zero(problem.qp.size()), r = problem.qp.b;
  int iterations = 0;
  std::vector<int> nested;
  if (method == "pdas") {
    PdasStep pdas(problem.qp);
    std::vector<char> last;
    for (; iterations < 100; ++iterations) {
      pdas.iterate(x, r);
      std::vector<char> active = problem.qp.active_set(x);
      if (active == last && problem.qp.feasible(x)) break;
      last = std::move(active);
    }
    ++iterations;
  } else {
    LevelHierarchy hierarchy = lowest.build_level_hierarchy();
    hierarchy.levels.push_back(order2_level(lowest.finest_space(), space));
    SolverOptions options = spec.solver;  // the case's options, for mmg
    options.method = SolverMethod::kMmg;
    const SolverReport report = solve_box_qp(problem.qp, hierarchy, options, {}, x);
    iterations = report.iterations;
    nested = report.nested_iterations;
    r = problem.qp.b - problem.qp.A * x;
  }
  const double solve_s = seconds_since(t1);
  const Vector full = assembler.full_vector(problem, x);
  const Point force = assembler.contact_force(full);
  const FunctionalParts parts = assembler.functional(full);
  nlohmann::json out = {{"order", 2},
                        {"refinements", spec.mesh.refinements},
                        {"dofs", problem.qp.size()},
                        {"force", {force.x(), force.y()}},
                        {"c3", data.weights.c3},
                        {"functional", parts.total()},
                        {"solver", method},
                        {"iterations", iterations},
                        {"nested_iterations", nested},
                        {"kkt_residual", problem.qp.kkt_residual(x, r)},
                        {"assembly_s", assembly_s},
                        {"solve_s", solve_s},
                        {"total_s", seconds_since(t0)}};
  std::cout << out.dump() << "\n";
  return 0;
}
