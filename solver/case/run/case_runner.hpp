#pragma once
// One call from a case to its result: mesh → hierarchy → assembly → solve → result JSON and
// VTU text. Used by the CLI and, in-process, by the job service.

#include <atomic>
#include <chrono>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/format/case_spec.hpp"
#include "core/box_qp.hpp"
#include "core/deadline.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "solvers/iteration_record.hpp"

namespace fosls {

struct RunControl {
  /// Called after every iteration from the solving thread; keep it cheap.
  std::function<void(const IterationRecord&)> on_iteration;
  /// Called before each solve of an adaptive run (and before the one solve of a uniform run)
  /// with the step, 0 first, and the unknowns of its level.
  std::function<void(int step, long long dofs)> on_step;
  /// Called before every solve of the run, after on_step: its index in the whole run, 0 first
  /// (a load step, sweep point, adaptive or accuracy level; a sweep of adaptive runs counts
  /// every level of every point), and most_solves(spec). For progress across a multi-solve run,
  /// whose iteration count starts again at each solve.
  std::function<void(int solve, int solves)> on_solve;
  /// When set and it becomes true, the solve stops at the next iteration and the result
  /// says "cancelled": true.
  const std::atomic<bool>* cancel = nullptr;
  /// Whether to produce the VTU text.
  bool want_vtu = true;
  /// Its arrays as ASCII text instead of base64 binary (post/vtu_writer.hpp).
  bool vtu_ascii = false;
  /// Limits of the mesher process (gmsh runs in a child process; see mesh/gmsh_mesh.hpp).
  MesherLimits mesher;
  /// Continuation: the solution of a case on the same mesh to start from (instead of the
  /// nested iteration); ignored when its size does not match.
  const Vector* start = nullptr;
  /// Load steps: called after every step but the last with the result the run would have if it
  /// stopped there (the steps solved so far, marked partial and cancelled), so that a process
  /// killed on cancel leaves them behind (the service's solve process sends it to its worker).
  std::function<void(const nlohmann::json& partial)> on_partial;
  /// Load steps: the displacement of each vertex of the finest mesh in the state the step
  /// starts from; friction measures slip from it (ignored when its size does not match).
  const std::vector<Point>* reference = nullptr;
};

struct RunOutput {
  nlohmann::json result;  ///< docs/result-format.md
  std::string vtu;        ///< VTK XML unstructured grid (empty unless want_vtu)
  bool cancelled = false;
  Vector solution;                  ///< the final iterate (unknowns of the QP), for continuation
  std::vector<Point> displacement;  ///< u at each vertex of the finest mesh, for load steps
};

/// solver.time_limit_s counted from `start`; none for a limit of 0.
Deadline run_deadline(std::chrono::steady_clock::time_point start, double time_limit_s);

/// How many solves run_case makes at most: load steps + 1, sweep points, adaptivity.steps + 1
/// per point (a product for a sweep of adaptive runs); 0 when not known before the run (an
/// accuracy loop stops once its estimate is within the tolerance, at a level it finds).
int most_solves(const CaseSpec& spec);

/// Everything that validation can say about a case JSON, including what needs the coarse mesh
/// (mesh errors, groups named in `boundary` that the mesh does not have, DOF limits).
/// Throws MeshingCancelled when `meshing.cancel` stopped the mesher.
std::vector<CaseError> validate_case(const nlohmann::json& j, const CaseReadOptions& options = {},
                                     const MeshingControl& meshing = {});

/// Runs a case from read_case, 2D or 3D (one point: point_runner.hpp); a case with load steps
/// or a sweep runs every point in order (load_step_runner.hpp, sweep_runner.hpp).
/// Throws CaseException for problems a user caused that show up only with the coarse mesh (mesh
/// errors, groups the mesh lacks, DOF limits: validate_case's checks, made here once the mesh is
/// built) or while running (for example weights that make the matrix indefinite). A cancel while
/// the coarse mesh is made returns at once with `cancelled` set and an empty result. Throws
/// TimeLimitReached (core/deadline.hpp), its message for the user, when solver.time_limit_s runs
/// out before the solve has an iterate (while the mesh is refined or the finest level assembled);
/// once it has one, the result is the last iterate with stop_reason time_limit.
RunOutput run_case(const CaseSpec& spec, const RunControl& control = {},
                   const CaseLimits& limits = {});

}  // namespace fosls
