#include "case/time_estimate.hpp"

#include <cmath>
#include <cstdio>

namespace fosls {

bool converges_on_fine_meshes(SolverMethod method) { return method != SolverMethod::kPgs; }

std::optional<double> estimated_seconds(long long unknowns, SolverMethod method) {
  const double n = static_cast<double>(unknowns);
  switch (method) {
    case SolverMethod::kMmg:
    case SolverMethod::kTnnmg:
      // O(N): the same iterations at every level (fitted on the solver table, two threads:
      // docs/performance.md, "Measurements behind choices in the code").
      return 0.1 + 25e-6 * n;
    case SolverMethod::kPdas:
      // The factorisation grows faster than N (the fit: docs/performance.md, "Measurements
      // behind choices in the code").
      return 9.6 * std::pow(n / 131200.0, 1.3);
    case SolverMethod::kPgs:
      return std::nullopt;
  }
  return std::nullopt;
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
