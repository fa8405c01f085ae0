#pragma once
// A rough guide to how long a solve takes, from its unknowns and method (docs/case-format.md,
// "Resources"): fitted on the curved-gap square on two cores of the development machine. The CLI
// prints it; the service bounds a whole case's time by it (job_time.hpp) only with a wide
// margin — the same run varies 2–3× with the machine's load.

#include <optional>
#include <string>

#include "solvers/solve_loop.hpp"

namespace fosls {

/// Whether the method's work stays bounded as the mesh is refined: mmg and tnnmg take about the
/// same iterations at every level, pdas solves each active set exactly. pgs is a baseline whose
/// iterations grow with the mesh: it does not converge on fine meshes within any usual
/// max_iterations, so advice never suggests it.
bool converges_on_fine_meshes(SolverMethod method);

/// Seconds for mesh, assembly, set-up and solve to the default tolerance; nothing for pgs,
/// whose iteration count grows with the mesh (it is a baseline, not expected to converge on
/// fine meshes).
std::optional<double> estimated_seconds(long long unknowns, SolverMethod method);

/// "about 0.81 s", "about 53 s", "about 6 min", "about 2.5 h": two significant digits in a
/// unit a reader takes in at a glance (not "3.5e+02 s").
std::string describe_seconds(double seconds);

}  // namespace fosls
