#include "case/admission/time_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fosls {

bool converges_on_fine_meshes(SolverMethod method) { return method != SolverMethod::kPgs; }

namespace {

/// 3D's fits follow the slowest of one thread's CPU time on a loaded machine over the Hertz ball
/// (λ = 1 and ∞), the incompressible block and the incompressible rounded punch, 9 868 to 638 000
/// unknowns (docs/performance.md, "3D: the time guide"): the punch's unstructured mesh costs
/// about twice the ball's per unknown, and a guide that bounds a job must cover both.
constexpr double kMeasured3d = 6.4e5;  ///< the largest 3D problem the fits saw

/// pdas: the factorisation grows faster than N. 2D: the fit of docs/performance.md,
/// "Measurements behind choices in the code"; 3D: N^1.4 where measured, and beyond it as a
/// nested-dissection factorisation's work in 3D, N².
double pdas_seconds(double n, int dimension) {
  if (dimension == 3) {
    const double measured = 0.8 + 10.3 * std::pow(std::min(n, kMeasured3d) / 79384.0, 1.4);
    return measured * std::pow(std::max(1.0, n / kMeasured3d), 2.0);
  }
  return 9.6 * std::pow(n / 131200.0, 1.3);
}

/// mmg and tnnmg without their coarsest level: O(N). 2D: the solver table, two threads
/// (docs/performance.md, "Measurements behind choices in the code"), the same for both; 3D:
/// tnnmg's linear cycle, projection and line search cost 1.6–2.8 times mmg's smoothing.
double multilevel_seconds(double n, int dimension, SolverMethod method) {
  if (dimension != 3) return 0.1 + 25e-6 * n;
  return 1.0 + (method == SolverMethod::kTnnmg ? 400e-6 : 260e-6) * n;
}

}  // namespace

std::optional<double> estimated_seconds(const ProblemCount& count, SolverMethod method) {
  const double n = static_cast<double>(count.unknowns);
  switch (method) {
    case SolverMethod::kMmg:
    case SolverMethod::kTnnmg: {
      // O(N): the same iterations at every level, and the coarsest level's direct solves.
      const double levels = multilevel_seconds(n, count.dimension, method);
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

double setup_share(SolverMethod method, int dimension) {
  if (method != SolverMethod::kPdas) return 0.3;
  // 3D's pdas factorises once per problem (solvers/bounded_complement_solver.hpp).
  return dimension == 3 ? 0.7 : 0.0;
}

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
