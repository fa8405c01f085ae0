#pragma once
// The 3D backend of run_case (case_runner.hpp) for a case of dimension 3: the tetrahedral mesh
// and its uniform refinements, the groups checked against the finest mesh, the P1³ × RT0³
// discretisation, the solve by mmg or pdas under the run's deadline, cancel and progress, and
// the result JSON (docs/result-format.md, "3D results"). The only file of the case layer that
// calls the 3D assembly, kept so for the unified finite-element stack (docs/architecture.md, "One
// case path for 2D and 3D").

#include "case/case_runner.hpp"

namespace fosls {

/// One 3D solve as run_case runs it. Throws CaseException for a problem only the mesh shows (an
/// unknown group, a contact face that does not face the plane, too many unknowns, a mesh source
/// that fails) and TimeLimitReached when solver.time_limit_s runs out before the first iterate.
RunOutput run_3d_point(const CaseSpec& spec, const RunControl& control, const CaseLimits& limits);

/// What validate_case says of a 3D case once its coarse mesh is built: the mesh source's
/// problems, the size against `limits`, the groups against the mesh.
std::vector<CaseError> check_3d_mesh(const CaseSpec& spec, const CaseLimits& limits);

}  // namespace fosls
