#include "case/resource_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fosls {

double bytes_per_unknown(SolverMethod method, int order) {
  if (order == 2) return method == SolverMethod::kPdas ? 3460 : 2040;  // mmg; the others refused
  // tests/benchmarks/memory_calibration.py, fitted on relative error; see docs/case-format.md.
  switch (method) {
    case SolverMethod::kMmg:
      return 766;
    case SolverMethod::kTnnmg:
      return 783;
    case SolverMethod::kPdas:
      return 2031;
    case SolverMethod::kPgs:
      return 482;
  }
  return 2031;
}

long long unknowns_after_refinement(long long triangles, long long edges, long long vertices,
                                    int refinements, int order) {
  long long nt = triangles, ne = edges, nv = vertices;
  for (int k = 0; k < refinements; ++k) {
    nv = nv + ne;
    ne = 2 * ne + 3 * nt;
    nt = 4 * nt;
  }
  return order == 2 ? 2 * nv + 6 * ne + 4 * nt : 2 * nv + 2 * ne;
}

long long estimated_unknowns_after_refinement(double triangles, double boundary_edges,
                                              int refinements, int order) {
  // A triangulated disk: 3T = 2E − B (every interior edge in two triangles) and V − E + T = 1.
  const double edges = (3 * triangles + boundary_edges) / 2;
  const double vertices = 1 + edges - triangles;
  return unknowns_after_refinement(std::llround(triangles), std::llround(edges),
                                   std::llround(vertices), refinements, order);
}

ResourceEstimate estimate_resources(long long unknowns, bool exact, SolverMethod method,
                                    int order) {
  return {unknowns, exact, kSolveBaseBytes + bytes_per_unknown(method, order) * unknowns,
          "/mesh/refinements", order};
}

ResourceEstimate estimate_adaptive_resources(long long max_dofs, SolverMethod method) {
  const bool levels = method == SolverMethod::kMmg || method == SolverMethod::kTnnmg;
  const double factor = levels ? kAdaptiveHierarchyFactor : 1.0;
  return {max_dofs, false, kSolveBaseBytes + factor * bytes_per_unknown(method) * max_dofs,
          "/adaptivity/max_dofs"};
}

long long accuracy_largest_unknowns(long long unknowns, long long max_dofs) {
  return std::max(unknowns, max_dofs);
}

std::string describe(const ResourceEstimate& e, SolverMethod method) {
  static const char* names[] = {"mmg", "tnnmg", "pdas", "pgs"};
  char text[160];
  const double mib = e.memory_bytes / (1 << 20);
  if (mib >= 1024)
    std::snprintf(text, sizeof text, "about %.3g GiB", mib / 1024);
  else
    std::snprintf(text, sizeof text, "about %.0f MiB", mib);
  return std::string(text) + " for " + (e.unknowns_exact ? "" : "about ") +
         std::to_string(e.unknowns) + " unknowns with " + names[static_cast<int>(method)];
}

}  // namespace fosls
