#include "case/admission/time_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fosls {

bool converges_on_fine_meshes(SolverMethod method) { return method != SolverMethod::kPgs; }

namespace {

/// pdas: the factorisation grows faster than N. 2D: the fit of docs/performance.md,
/// "Measurements behind choices in the code"; 3D: the Hertz ball at refinement 3 on a slower
/// machine, the incompressible punch and block (docs/performance.md, "3D"), growing with the
/// fill-in beyond the 6.4·10⁵ unknowns where it was measured.
double pdas_seconds(double n, int dimension) {
  if (dimension == 3) return 1.0 + 300e-6 * std::max(1.0, std::sqrt(n / 6.4e5)) * n;
  return 9.6 * std::pow(n / 131200.0, 1.3);
}

}  // namespace

std::optional<double> estimated_seconds(const ProblemCount& count, SolverMethod method) {
  const double n = static_cast<double>(count.unknowns);
  const bool three = count.dimension == 3;
  switch (method) {
    case SolverMethod::kMmg:
    case SolverMethod::kTnnmg: {
      // O(N): the same iterations at every level (2D fitted on the solver table, two threads:
      // docs/performance.md, "Measurements behind choices in the code"; 3D the slowest measured
      // with contact, the incompressible rounded punch), and the coarsest level's direct solves.
      const double levels = three ? 1.0 + 260e-6 * n : 0.1 + 25e-6 * n;
      const double coarse = static_cast<double>(count.coarse_unknowns);
      return levels + (coarse > 0 ? 2.0 * pdas_seconds(coarse, count.dimension) : 0.0);
    }
    case SolverMethod::kPdas:
      return pdas_seconds(n, count.dimension);
    case SolverMethod::kPgs:
      return std::nullopt;
  }
  return std::nullopt;
}

int fitted_iterations(SolverMethod method, int dimension) {
  if (method == SolverMethod::kPdas) return 10;
  return dimension == 3 ? 30 : 14;
}

double setup_share(SolverMethod method) { return method == SolverMethod::kPdas ? 0.0 : 0.3; }

std::string describe_seconds(double seconds) {
  char text[48];
  if (seconds < 99.5)
    std::snprintf(text, sizeof text, "about %.2g s", seconds);
  else if (seconds < 99.5 * 60)
    std::snprintf(text, sizeof text, "about %.2g min", seconds / 60);
  else
    std::snprintf(text, sizeof text, seconds < 99.5 * 3600 ? "about %.2g h" : "about %.0f h",
                  seconds / 3600);
  return text;
}

}  // namespace fosls
