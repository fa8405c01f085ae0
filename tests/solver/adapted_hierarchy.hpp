#pragma once
// Nested hierarchies made by the adaptive loop (solve → estimate → Dörfler → bisect), for the
// solver tests: the uniform levels of a coarse mesh followed by `steps` bisection levels.

#include "assembly/discretization.hpp"
#include "assembly/error_indicators.hpp"
#include "mesh/bisection.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls::testing {

/// Each step solves the finest level with pdas and refines the Dörfler set of θ = 0.5.
inline MeshHierarchy adapted_hierarchy(MeshHierarchy meshes, const ProblemData<2>& data,
                                       int steps) {
  BisectionState state = longest_edge_state(meshes.finest(), 2 * (meshes.num_levels() - 1));
  for (int step = 0; step < steps; ++step) {
    const Discretization disc(meshes, data);
    SolverOptions options;
    options.method = SolverMethod::kPdas;
    Vector x;
    solve_box_qp(disc.problem().qp, LevelHierarchy{}, options, {}, x);
    const FunctionalParts parts =
        disc.assembler().functional(disc.assembler().full_vector(disc.problem(), x));
    refine_finest_level(meshes, state, dorfler_marking(error_estimate(parts).indicators, 0.5));
  }
  return meshes;
}

}  // namespace fosls::testing
