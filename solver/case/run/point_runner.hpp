#pragma once
// One point of a case, written once for 2D and 3D (docs/architecture.md, "One case path for 2D
// and 3D"):
//   1. the coarse mesh from the case's source, checked (case_mesh.hpp);
//   2. its uniform refinements, and in 3D the groups checked again on the finest mesh;
//   3. the problem data, with the functional's length scale and c3 "auto" chosen;
//   4. the solve on the levels, adaptive or towards an accuracy when asked
//   (strategy/level_loop.hpp);
//   5. the result JSON, the warnings and the VTU.
// run_case (case_runner.hpp) runs one point, or repeats it for load steps and sweeps.

#include "case/run/case_runner.hpp"

namespace fosls {

/// One solve of `spec` as run_case runs it; the same throws (CaseException, TimeLimitReached).
template <int dim>
RunOutput run_point(const CaseSpec& spec, const RunControl& control, const CaseLimits& limits);

}  // namespace fosls
