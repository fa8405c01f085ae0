// Benchmark (not a test): the fixed point of Coulomb friction's slip bounds, measured apart from
// the solver's update schedule (issue 49; docs/performance.md, "Coulomb: the bounds updated
// every third iteration (issue 49)"). It takes a case with Coulomb friction (one load step):
//
//   build/bin/coulomb-lab CASE.json fixed [refinements=N] [outer=14] [tolerance=1e-10]
//     The method of successive approximations done exactly: each outer step solves the Tresca
//     problem with the current slip bounds to the KKT tolerance (mmg, warm-started), then sets
//     the bounds s̄_e = 𝔣 max(0, −S_n,e) from that solution. Prints per outer step the inner
//     iterations and the largest relative change of a bound, and the contraction factor (the
//     geometric mean of the last three ratios of changes): below 1 the fixed point contracts,
//     near 1 or oscillating it does not.
//
//   build/bin/coulomb-lab CASE.json coupled [refinements=N] [iterations=40]
//     The linear stability of the coupled iteration at the fixed point: the fixed point is
//     computed as above, its bounds perturbed by ±0.5 %, and single mmg iterations alternate
//     with bound updates (the S_t of a slipping edge moved onto its new bound). Prints the
//     distance to the fixed point per iteration, split into S_n, S_t, U_t and the rest.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../case_discretization.hpp"
#include "assembly/discretization.hpp"
#include "assembly/friction_terms.hpp"
#include "case/format/case_reader.hpp"
#include "solvers/solve_loop.hpp"

using namespace fosls;

namespace {

/// `name=value` from the command line, or `fallback`.
double argument(int argc, char** argv, const std::string& name, double fallback) {
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind(name + "=", 0) == 0) return std::atof(a.c_str() + name.size() + 1);
  }
  return fallback;
}

/// The case's discretisation at the requested refinements (built in place: the level
/// hierarchy refers to it).
struct Lab {
  std::unique_ptr<Discretization<2>> disc;
  LevelHierarchy hierarchy;
  SolverOptions options;
};

std::unique_ptr<Discretization<2>> discretize(CaseSpec& spec, int refinements) {
  if (refinements >= 0) spec.mesh.refinements = refinements;
  return testing::case_discretization(spec);
}

/// One Tresca solve with the current bounds from x (nested iteration only the first time).
SolverReport tresca_solve(Lab& lab, Vector& x, bool first) {
  AssembledProblem& problem = lab.disc->mutable_problem();
  KinkedProblem kinked;
  kinked.kinks = &problem.kinks;
  SolverOptions options = lab.options;
  options.nested = first && options.nested;
  return solve_kinked_qp(problem.qp, kinked, lab.hierarchy, options, {}, x);
}

/// The bounds from x's S_n; with `keep_slip` the S_t of an edge that slipped on its old bound
/// is put on its new one. x is clipped to the new bounds. Returns the relative change.
double update_bounds(AssembledProblem& problem, Vector& x, bool keep_slip) {
  const auto& edges = problem.friction.edges;
  std::vector<int> side(edges.size(), 0);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int i = edges[e].st;
    if (problem.qp.upper[i] > 0.0 && x[i] >= problem.qp.upper[i]) side[e] = 1;
    if (problem.qp.upper[i] > 0.0 && x[i] <= problem.qp.lower[i]) side[e] = -1;
  }
  const double change = set_friction_bounds(problem.friction, x, problem.qp, problem.kinks);
  for (std::size_t e = 0; keep_slip && e < edges.size(); ++e)
    if (side[e])
      x[edges[e].st] = side[e] > 0 ? problem.qp.upper[edges[e].st] : problem.qp.lower[edges[e].st];
  problem.qp.clip(x);
  return change;
}

/// Successive approximations to `outer` steps or a change below `stop`; prints a row per step
/// when `verbose`. Returns the changes.
std::vector<double> fixed_point(Lab& lab, Vector& x, int outer, double stop, bool verbose) {
  std::vector<double> changes;
  for (int k = 0; k < outer; ++k) {
    const SolverReport rep = tresca_solve(lab, x, k == 0);
    const double change = update_bounds(lab.disc->mutable_problem(), x, false);
    changes.push_back(change);
    if (verbose) {
      std::printf("| %d | %d%s | %.3e | %s |\n", k, rep.iterations,
                  rep.converged ? "" : " (not conv.)", change,
                  k == 0 ? "—" : std::to_string(change / changes[k - 1]).substr(0, 5).c_str());
      std::fflush(stdout);
    }
    if (change < stop) break;
  }
  return changes;
}

void run_fixed(Lab& lab, int outer) {
  std::printf("| outer step | inner mmg iterations | bound change | ratio |\n|---|---|---|---|\n");
  Vector x;
  const std::vector<double> changes = fixed_point(lab, x, outer, 1e-9, true);
  const int n = static_cast<int>(changes.size());
  if (n >= 5 && changes.back() >= 1e-9) {
    const double factor = std::pow(changes[n - 1] / changes[n - 4], 1.0 / 3.0);
    std::printf("contraction factor (last three steps): %.3f\n", factor);
  } else {
    std::printf("converged after %d outer steps (change %.1e)\n", n, changes.back());
  }
}

/// ‖x − xs‖ split into the rest, S_n, S_t and U_t of the frictional edges.
std::vector<double> split_distance(const AssembledProblem& problem, const Vector& x,
                                   const Vector& xs) {
  std::vector<int> kind(x.size(), 0);
  for (const FrictionEdge& f : problem.friction.edges) kind[f.sn] = 1, kind[f.st] = 2;
  for (int d : problem.kinks.dof) kind[d] = 3;
  std::vector<double> n(4, 0.0);
  for (int i = 0; i < x.size(); ++i) n[kind[i]] += (x[i] - xs[i]) * (x[i] - xs[i]);
  for (double& v : n) v = std::sqrt(v);
  return n;
}

void run_coupled(Lab& lab, int iterations) {
  AssembledProblem& problem = lab.disc->mutable_problem();
  Vector x;
  lab.options.max_iterations = std::max(lab.options.max_iterations, 60);
  const std::vector<double> changes = fixed_point(lab, x, 30, 1e-11, false);
  std::printf("fixed point: %zu outer steps, last change %.1e\n", changes.size(), changes.back());
  const Vector xs = x;
  std::srand(1);
  for (const FrictionEdge& f : problem.friction.edges) {
    const double s = problem.qp.upper[f.st];
    const double perturbed = s * (1.0 + 0.01 * (std::rand() / static_cast<double>(RAND_MAX) - 0.5));
    const bool slipping = s > 0.0 && std::abs(x[f.st]) >= s;
    problem.qp.upper[f.st] = perturbed, problem.qp.lower[f.st] = -perturbed;
    if (slipping) x[f.st] = std::copysign(perturbed, x[f.st]);
  }
  std::printf("| iteration | rest | S_n | S_t | U_t |\n|---|---|---|---|---|\n");
  lab.options.max_iterations = 1;
  for (int k = 0; k <= iterations; ++k) {
    const std::vector<double> d = split_distance(problem, x, xs);
    std::printf("| %d | %.3e | %.3e | %.3e | %.3e |\n", k, d[0], d[1], d[2], d[3]);
    std::fflush(stdout);
    tresca_solve(lab, x, false);
    update_bounds(problem, x, true);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || (std::string(argv[2]) != "fixed" && std::string(argv[2]) != "coupled")) {
    std::cerr << "usage: coulomb-lab CASE.json fixed|coupled [refinements=N] [outer=N] "
                 "[tolerance=T] [iterations=N]\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::cerr << argv[1] << ": cannot be read\n";
    return 2;
  }
  CaseReadResult read = read_case(nlohmann::json::parse(in));
  if (!read.spec) {
    std::cerr << read.errors[0].pointer << ": " << read.errors[0].detail << "\n";
    return 2;
  }
  CaseSpec spec = *read.spec;
  Lab lab;
  lab.disc = discretize(spec, static_cast<int>(argument(argc, argv, "refinements", -1)));
  lab.hierarchy = lab.disc->build_level_hierarchy();
  lab.options = spec.solver;
  if (!lab.disc->mutable_problem().friction.coulomb()) {
    std::cerr << argv[1] << ": /boundary: no contact group with a friction coefficient\n";
    return 2;
  }
  lab.options.tolerance = argument(argc, argv, "tolerance", 1e-10);
  std::printf("unknowns %d, frictional edges %zu\n", lab.disc->mutable_problem().qp.size(),
              lab.disc->mutable_problem().friction.edges.size());
  if (std::string(argv[2]) == "fixed")
    run_fixed(lab, static_cast<int>(argument(argc, argv, "outer", 14)));
  else
    run_coupled(lab, static_cast<int>(argument(argc, argv, "iterations", 40)));
  return 0;
}
