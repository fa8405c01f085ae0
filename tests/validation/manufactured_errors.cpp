// The FOSLS functional as an error estimator, measured against the true error of a
// manufactured solution (docs/validation.md, "Error estimator").
//
// Unit square, u = (sin πx cos πy, −cos πx sin πy), σ = 2μ ε(u), f = −div σ = 2π²μ u: the
// exact solution for every λ including λ = ∞ (div u = 0), Dirichlet data on the left and
// bottom sides, Neumann data t = σn on the right and top sides (the same problem as
// tests/validation/manufactured_square.json, which the CLI solves). For each level the
// program solves the discrete problem with CHOLMOD (no contact: a linear problem) and
// compares, triangle by triangle, the functional η_T² (the estimator the solver reports) with
// the true error e_T² = ‖u − u_h‖²_H¹(T) + ‖σ − σ_h‖²_L²(T) + ‖div(σ − σ_h)‖²_L²(T).
//
// Usage: validation_manufactured_errors [--lambda 1|inf] [--levels N] [--size H]
//                                       [--elements R]
// Prints one JSON object with a row per level; the row of refinement R also lists η_T² and
// e_T² of every triangle.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "assembly/discretization.hpp"
#include "mesh/builtin_meshes.hpp"
#include "validation/measured_solve.hpp"
#include "verification/verification_problems.hpp"

namespace {

using fosls::Point;

using SmoothSolution = fosls::testing::SmoothSolution;

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * (v.size() - 1);
  const auto i = static_cast<std::size_t>(pos);
  if (i + 1 >= v.size()) return v.back();
  return v[i] + (pos - i) * (v[i + 1] - v[i]);
}

nlohmann::json level_row(const SmoothSolution& sol, double lambda, double size, int refinements,
                         bool with_elements) {
  fosls::Discretization<2> disc(
      fosls::build_mesh_hierarchy(fosls::make_square({.size = size}), refinements),
      sol.problem(lambda));
  const auto& p = disc.problem();
  const fosls::testing::MeasuredSolve m = fosls::testing::measure_linear_solve(disc, sol.exact());
  const fosls::FunctionalParts& parts = m.parts;
  const fosls::Mesh& mesh = disc.meshes().finest();
  const auto& total = m.total;
  const auto& true_error = m.element_error;
  // Local efficiency η_T / e_T: bounded above by the norm equivalence, not below (the
  // estimator's reliability is global), so its spread is part of the picture.
  std::vector<double> ratio(mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); ++t)
    ratio[t] = std::sqrt(parts.element[t] / true_error[t]);
  const double error = m.error();
  const double j = parts.total();
  nlohmann::json row = {
      {"refinements", refinements},
      {"dofs", p.qp.size()},
      {"triangles", mesh.num_triangles()},
      {"h_max", mesh.edge_length_range().second},
      {"functional",
       {{"total", j}, {"momentum", parts.momentum}, {"constitutive", parts.constitutive}}},
      {"error",
       {{"u_l2", std::sqrt(total[0])},
        {"grad_u_l2", std::sqrt(total[1])},
        {"sigma_l2", std::sqrt(total[2])},
        {"div_sigma_l2", std::sqrt(total[3])},
        {"norm", error}}},
      {"efficiency", std::sqrt(j) / error},
      {"local_efficiency",
       {{"min", quantile(ratio, 0.0)},
        {"p05", quantile(ratio, 0.05)},
        {"median", quantile(ratio, 0.5)},
        {"p95", quantile(ratio, 0.95)},
        {"max", quantile(ratio, 1.0)}}}};
  if (with_elements) {
    row["element_functional"] = parts.element;  // η_T²
    row["element_error"] = true_error;          // e_T²
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  double lambda = 1.0, size = 0.25;
  int levels = 5, elements = -1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) {
      std::cerr << "usage: " << argv[0]
                << " [--lambda 1|inf] [--levels N] [--size H] [--elements R]\n";
      return 2;
    }
    const std::string value = argv[++i];
    if (arg == "--lambda")
      lambda = value == "inf" ? std::numeric_limits<double>::infinity() : std::stod(value);
    else if (arg == "--levels")
      levels = std::stoi(value);
    else if (arg == "--size")
      size = std::stod(value);
    else if (arg == "--elements")
      elements = std::stoi(value);
    else {
      std::cerr << "unknown option " << arg << '\n';
      return 2;
    }
  }
  if (levels < 1 || levels > 8 || !(size > 0) || !(lambda >= 0)) {
    std::cerr << "need 1 <= levels <= 8, size > 0, lambda >= 0\n";
    return 2;
  }
  const SmoothSolution sol;
  nlohmann::json out = {
      {"lambda", std::isinf(lambda) ? nlohmann::json("inf") : nlohmann::json(lambda)},
      {"size", size},
      {"rows", nlohmann::json::array()}};
  for (int r = 0; r < levels; ++r)
    out["rows"].push_back(level_row(sol, lambda, size, r, r == elements));
  std::cout << out.dump(1) << '\n';
  return 0;
}
