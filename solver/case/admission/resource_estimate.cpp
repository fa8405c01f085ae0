#include "case/admission/resource_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "case/admission/memory_size.hpp"
#include "solvers/coulomb_fallback.hpp"

namespace fosls {

double bytes_per_unknown(SolverMethod method, int order, int dimension) {
  // 3D: the largest measured with contact (docs/performance.md, "3D"); mmg and pdas only.
  if (dimension == 3) return method == SolverMethod::kPdas ? 8000 : 2200;
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

double direct_factorisation_bytes(long long unknowns, SolverMethod method, int dimension) {
  if (method == SolverMethod::kPgs || unknowns <= 0) return 0;
  const double n = static_cast<double>(unknowns);
  const bool pdas = method == SolverMethod::kPdas;
  // Fitted at refinements 0, less the base: 3D on the box (21 771 to 166 803 unknowns), 2D on
  // the square (docs/case-format.md, "Resources").
  if (dimension == 3) return (pdas ? 104.0 : 212.0) * std::pow(n, 4.0 / 3.0);
  return (pdas ? kPdasFactorBytes2d : kMultilevelCoarseBytes2d) * n * std::log2(n);
}

namespace {

bool multilevel(SolverMethod method) {
  return method == SolverMethod::kMmg || method == SolverMethod::kTnnmg;
}

/// `slope_factor` scales the finest level's slope (an adaptive hierarchy's levels).
ResourceEstimate priced(long long unknowns, const ProblemCount& count, SolverMethod method,
                        double slope_factor) {
  ResourceEstimate e;
  e.unknowns = unknowns;
  e.unknowns_exact = count.exact;
  e.order = count.order;
  e.coarse_unknowns = count.coarse_unknowns;
  e.dimension = count.dimension;
  e.coulomb = count.coulomb;
  const double base = count.dimension == 3 ? kSolveBaseBytes3d : kSolveBaseBytes;
  const double slope = slope_factor * bytes_per_unknown(method, count.order, count.dimension) *
                       static_cast<double>(unknowns);
  if (method == SolverMethod::kPdas)
    e.factorisation_bytes =
        std::max(0.0, direct_factorisation_bytes(unknowns, method, count.dimension) - slope);
  else if (multilevel(method))
    e.factorisation_bytes =
        direct_factorisation_bytes(count.coarse_unknowns, method, count.dimension);
  ProblemCount finest = count;
  finest.unknowns = unknowns;
  e.fallback_bytes = fallback_bytes(finest, method);
  e.memory_bytes = base + slope + e.factorisation_bytes + e.fallback_bytes;
  return e;
}

}  // namespace

double fallback_bytes(const ProblemCount& count, SolverMethod method) {
  // solvers/solve_loop.cpp switches only mmg on a 2D Coulomb problem of at most this size.
  if (!count.coulomb || method != SolverMethod::kMmg || count.dimension != 2 ||
      count.unknowns > kFallbackMaxUnknowns)
    return 0;
  const double n = static_cast<double>(count.unknowns);
  const double pdas = std::max(bytes_per_unknown(SolverMethod::kPdas, count.order, 2) * n,
                               direct_factorisation_bytes(count.unknowns, SolverMethod::kPdas, 2));
  return std::max(0.0, pdas - bytes_per_unknown(SolverMethod::kMmg, count.order, 2) * n);
}

ResourceEstimate estimate_resources(const ProblemCount& count, SolverMethod method) {
  return priced(count.unknowns, count, method, 1.0);
}

ResourceEstimate estimate_adaptive_resources(long long max_dofs, const ProblemCount& count,
                                             SolverMethod method) {
  ResourceEstimate e =
      priced(max_dofs, count, method, multilevel(method) ? kAdaptiveHierarchyFactor : 1.0);
  e.unknowns_exact = false;
  e.limited_by = "/adaptivity/max_dofs";
  return e;
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
  std::string s = std::string(text) + " for " + (e.unknowns_exact ? "" : "about ") +
                  std::to_string(e.unknowns) + " unknowns with " + names[static_cast<int>(method)];
  // Say where the memory goes when the direct factorisation is a large part of it.
  if (e.fallback_bytes > 0.25 * e.memory_bytes)
    s += " (" + format_bytes(e.fallback_bytes) +
         " of it for Coulomb's fallback to pdas, which factorises the whole problem where mmg "
         "stalls, up to " +
         std::to_string(kFallbackMaxUnknowns) + " unknowns)";
  else if (e.factorisation_bytes > 0.25 * e.memory_bytes)
    s += method == SolverMethod::kPdas
             ? " (its direct factorisation)"
             : " (" + format_bytes(e.factorisation_bytes) + " of it the direct factorisation of " +
                   std::to_string(e.coarse_unknowns) + " coarsest-level unknowns)";
  return s;
}

}  // namespace fosls
