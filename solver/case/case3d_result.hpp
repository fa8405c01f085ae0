#pragma once
// The result JSON of a 3D case (docs/result-format.md, "3D results"): the solve, the mesh, the
// contact force as a 3-vector, the contact area and peak pressure, J, and the warnings a 2D
// result would give for the same finding (no_contact, initial_penetration, not_converged).

#include <nlohmann/json.hpp>

#include "assembly/discretization.hpp"
#include "case/case_spec.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

/// Everything but `timing`, which the runner adds.
nlohmann::json case3d_result(const CaseSpec& spec, const Discretization<3>& disc,
                             const Vector& x_free, const SolverReport& report);

}  // namespace fosls
