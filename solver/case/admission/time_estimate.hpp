#pragma once
// A rough guide to how long a solve takes, from its unknowns and method (docs/case-format.md,
// "Resources"): in 2D fitted on the curved-gap square on two cores of the development machine,
// in 3D on the slowest of one thread's CPU time on four cases (docs/performance.md, "3D: the time
// guide"). The CLI prints it; the
// service bounds a whole case's time by it (job_time.hpp) only with a wide margin — the same run
// varies 2–3× with the machine's load.

#include <optional>
#include <string>

#include "case/admission/resource_estimate.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

/// Whether the method's work stays bounded as the mesh is refined: mmg and tnnmg take about the
/// same iterations at every level, pdas solves each active set exactly. pgs is a baseline whose
/// iterations grow with the mesh: it does not converge on fine meshes within any usual
/// max_iterations, so advice never suggests it.
bool converges_on_fine_meshes(SolverMethod method);

/// Seconds for mesh, assembly, set-up and solve to the default tolerance in about
/// fitted_iterations(method, dimension) iterations; nothing for pgs, whose iteration count grows
/// with the mesh (it is a baseline, not expected to converge on fine meshes). mmg and tnnmg add
/// the direct solves of their coarsest level: about twice pdas's time on its unknowns (measured
/// 1.4 to 2.6 times on the square at refinements 0).
std::optional<double> estimated_seconds(const ProblemCount& count, SolverMethod method);

/// The iterations the fits of estimated_seconds ran: the shipped frictionless examples' mmg
/// takes 13–14 (2D) and 23–29 (3D), pdas 5–10.
int fitted_iterations(SolverMethod method, int dimension);

/// The share of estimated_seconds that does not grow with the iterations (mesh, assembly, the
/// hierarchy and the nested iteration): mmg and tnnmg about 0.3; pdas 0 in 2D, where it
/// factorises per active set, and 0.7 in 3D, where one factorisation serves every active set
/// (measured 0.74 on the Hertz ball at 79 384 unknowns).
double setup_share(SolverMethod method, int dimension);

/// "about 0.81 s", "about 53 s", "about 6 min", "about 2.5 h": two significant digits in a
/// unit a reader takes in at a glance (not "3.5e+02 s").
std::string describe_seconds(double seconds);

}  // namespace fosls
