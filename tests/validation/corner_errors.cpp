// The true error and the estimator J^½ on the L-shaped domain with a corner singularity
// (tests/validation/corner_solution.hpp), on uniform and on adaptive meshes
// (docs/validation.md §11).
//
// Uniform: the coarse mesh and its red refinements. Adaptive: from the same coarse mesh, a loop
// of the parts the case runner's loop uses (solver/strategy/level_loop.hpp) — η_T² = the
// functional on T, Dörfler marking with θ, newest-vertex bisection with closure — with every
// discrete problem solved exactly by CHOLMOD (no contact: the problem is linear), so that the
// error measured is the discretisation error alone. Per mesh: unknowns, J^½, the true error
// (‖u − u_h‖²_H¹ + ‖σ − σ_h‖²_H(div))^½ and the efficiency J^½ / error.
//
// Usage: validation_corner_errors [--lambda 1|inf] [--coarse N] [--levels L] [--theta T]
//                                 [--max-dofs M] [--beta B]
// (--beta 2: u linear, reproduced exactly, a check of the data and the norms).
// Prints one JSON object {lambda, theta, uniform: [rows], adaptive: [rows]}.
#include <cmath>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "assembly/error_indicators.hpp"
#include "mesh/bisection.hpp"
#include "validation/corner_solution.hpp"
#include "validation/measured_solve.hpp"

namespace {

using fosls::testing::CornerSolution;

nlohmann::json row_of(const fosls::Discretization<2>& disc,
                      const fosls::testing::MeasuredSolve& m) {
  const double estimator = std::sqrt(m.parts.total());
  return {{"dofs", disc.problem().qp.size()},
          {"triangles", disc.meshes().finest().num_triangles()},
          {"estimator", estimator},
          {"error", m.error()},
          {"grad_u_l2", std::sqrt(m.total[1])},
          {"sigma_l2", std::sqrt(m.total[2])},
          {"div_sigma_l2", std::sqrt(m.total[3])},
          {"momentum", m.parts.momentum},
          {"constitutive", m.parts.constitutive},
          {"efficiency", estimator / m.error()}};
}

struct Options {
  double lambda = 1.0;
  int coarse = 2;  ///< squares per unit length of the coarse mesh
  int levels = 6;  ///< uniform meshes: the coarse one and levels − 1 refinements
  double theta = 0.5;
  double beta = 5.0 / 3.0;      ///< CornerSolution::beta
  long long max_dofs = 100000;  ///< the adaptive loop stops at the first mesh beyond this
};

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) {
      std::cerr << "usage: " << argv[0]
                << " [--lambda 1|inf] [--coarse N] [--levels L] [--theta T] [--max-dofs M]"
                   " [--beta B]\n";
      return 2;
    }
    const std::string value = argv[++i];
    if (arg == "--lambda")
      o.lambda = value == "inf" ? std::numeric_limits<double>::infinity() : std::stod(value);
    else if (arg == "--coarse")
      o.coarse = std::stoi(value);
    else if (arg == "--levels")
      o.levels = std::stoi(value);
    else if (arg == "--beta")
      o.beta = std::stod(value);
    else if (arg == "--theta")
      o.theta = std::stod(value);
    else if (arg == "--max-dofs")
      o.max_dofs = std::stoll(value);
    else {
      std::cerr << "unknown option " << arg << '\n';
      return 2;
    }
  }
  if (o.coarse < 1 || o.levels < 1 || o.levels > 8 || !(o.theta > 0 && o.theta <= 1) ||
      !(o.lambda >= 0) || o.max_dofs < 1) {
    std::cerr << "need coarse >= 1, 1 <= levels <= 8, 0 < theta <= 1, lambda >= 0\n";
    return 2;
  }
  const CornerSolution sol{.beta = o.beta};
  const fosls::ExactSolution exact = sol.exact();
  const fosls::ProblemData<2> data = sol.problem(o.lambda);
  const fosls::Mesh coarse = fosls::testing::corner_mesh(o.coarse);
  nlohmann::json out = {
      {"lambda", std::isinf(o.lambda) ? nlohmann::json("inf") : nlohmann::json(o.lambda)},
      {"theta", o.theta},
      {"uniform", nlohmann::json::array()},
      {"adaptive", nlohmann::json::array()}};

  for (int r = 0; r < o.levels; ++r) {
    const fosls::Discretization<2> disc(fosls::build_mesh_hierarchy(coarse, r), data);
    out["uniform"].push_back(row_of(disc, fosls::testing::measure_linear_solve(disc, exact)));
  }

  // Only the finest mesh is kept: a direct solve needs no hierarchy.
  fosls::MeshHierarchy meshes = fosls::build_mesh_hierarchy(coarse, 0);
  fosls::BisectionState state = fosls::longest_edge_state(meshes.finest());
  for (;;) {
    const fosls::Discretization<2> disc(meshes, data);
    const fosls::testing::MeasuredSolve m = fosls::testing::measure_linear_solve(disc, exact);
    nlohmann::json row = row_of(disc, m);
    const bool last = disc.problem().qp.size() > o.max_dofs;
    const std::vector<int> marked =
        last ? std::vector<int>{}
             : fosls::dorfler_marking(fosls::error_estimate(m.parts).indicators, o.theta);
    row["marked"] = marked.size();
    out["adaptive"].push_back(row);
    if (marked.empty()) break;
    fosls::refine_finest_level(meshes, state, marked);
    meshes.meshes.erase(meshes.meshes.begin());
    meshes.maps.erase(meshes.maps.begin());
  }
  std::cout << out.dump(1) << '\n';
  return 0;
}
