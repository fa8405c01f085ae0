// A 3D case, step by step: the coarse mesh from its source, the hierarchy of uniform
// refinements, the boundary groups checked against the mesh, the problem data, the solve, the
// result.

#include "case/solve3d_backend.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "assembly/discretization.hpp"
#include "case/adaptive_runner.hpp"
#include "case/case3d_result.hpp"
#include "case/case_admission.hpp"
#include "case/case_error.hpp"
#include "case/case_problem_data.hpp"
#include "case/early_group_check.hpp"
#include "case/expression.hpp"
#include "case/mesh_factory.hpp"
#include "case/solve3d_checks.hpp"
#include "case/solve_observer.hpp"
#include "core/indefinite_system.hpp"
#include "core/non_finite.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "mesh/length_scale.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/tet_msh_reader.hpp"
#include "mesh/tet_refinement.hpp"
#include "post/tet_vtu_writer.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

namespace {

/// Below this ratio of its smallest to its largest extent an indefinite matrix is put down to
/// the body's thinness rather than the weights (a 1 x 1 x 1e-9 plate fails; 1e-3 solves).
constexpr double kThinnestBody = 1e-6;

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Step 1: the coarse mesh from the case's source; its problems at the source's pointer.
TetMesh coarse_mesh(const MeshSpec& m) {
  try {
    switch (m.kind) {
      case MeshSpec::Kind::kBuiltin: {
        auto mesh = builtin_3d_mesh(m);
        if (auto* errors = std::get_if<std::vector<CaseError>>(&mesh))
          throw CaseException(std::move(*errors));
        return std::move(std::get<TetMesh>(mesh));
      }
      case MeshSpec::Kind::kMsh:
        return tet_mesh_from_msh(m.msh_text);
      case MeshSpec::Kind::kGeoFile:
        return tet_mesh_from_geo_file(m.geo_path, m.size);
      case MeshSpec::Kind::kGeometry:
        break;  // refused by the reader in 3D
    }
  } catch (const MeshError& e) {
    std::vector<CaseError> errors;
    for (const auto& p : e.problems())
      errors.push_back(
          {p.field == "/size" ? std::string("/mesh/size") : mesh_source_pointer(m), p.detail});
    throw CaseException(std::move(errors));
  }
  throw CaseException(mesh_source_pointer(m), "unknown mesh source");
}

/// Refuses refinements whose finest level would exceed the limits (case_admission.hpp).
void check_size_of(double coarse_unknowns, bool exact, const CaseSpec& spec,
                   const CaseLimits& limits) {
  const ProblemCount count{std::llround(finest_3d_unknowns(coarse_unknowns, spec.mesh.refinements)),
                           std::llround(coarse_unknowns), exact, spec.mesh.order, 3};
  std::vector<CaseError> errors = check_size(spec, count, limits);
  if (!errors.empty()) throw CaseException(std::move(errors));
}

/// Step 3: every named group is one of the mesh's, and every contact face faces its plane.
void check_groups(const CaseSpec& spec, const TetMesh& mesh) {
  std::vector<CaseError> errors = check_3d_groups(spec, mesh);
  if (!errors.empty()) throw CaseException(std::move(errors));
}

/// A FOSLS matrix that is not positive definite in 3D: a body too thin for double precision
/// (its stiffness across and along differ by more than it can hold), or the weights.
CaseException indefinite_3d(const CaseSpec& spec, const TetMesh& mesh, const std::string& found) {
  Point3 lo = mesh.vertex(0), hi = mesh.vertex(0);
  for (int v = 1; v < mesh.num_vertices(); ++v) {
    lo = lo.cwiseMin(mesh.vertex(v));
    hi = hi.cwiseMax(mesh.vertex(v));
  }
  const Point3 extent = hi - lo;
  const double thinness = extent.minCoeff() / extent.maxCoeff();
  std::ostringstream m;
  if (thinness < kThinnestBody) {
    m << "the body is " << extent.minCoeff() << " thin and " << extent.maxCoeff()
      << " across (a ratio of " << thinness
      << "): its FOSLS matrix is not positive definite in double precision. Model a body this "
         "thin as a plate or a 2D case, or make it thicker";
    return CaseException("/mesh", m.str());
  }
  const Weights& w = spec.weights;
  m << "the weights c1 = " << w.c1 << ", c2 = " << w.c2 << ", c3 = " << w.c3 << ", c4 = " << w.c4
    << " make the FOSLS matrix not positive definite (the contact term c3 is too large relative "
       "to c1 and c2: "
    << (w.c3_auto ? "c3 was chosen as half the limit " + std::to_string(w.c3_limit) +
                        " computed on a coarser level; give a smaller c3 by hand"
                  : std::string("give a smaller c3, or \"auto\" to have it chosen"))
    << "); with null displacement components, also check that the dirichlet groups leave no "
       "rigid motion (found by the solver: "
    << found << ")";
  return CaseException("/weights", m.str());
}

}  // namespace

std::vector<CaseError> check_3d_mesh(const CaseSpec& spec, const CaseLimits& limits) {
  try {
    if (const auto unknowns = builtin_3d_unknowns(spec.mesh))
      check_size_of(*unknowns, false, spec, limits);
    const TetMesh coarse = coarse_mesh(spec.mesh);
    check_size_of(tet_mesh_unknowns(coarse), true, spec, limits);
    return check_3d_groups(spec, coarse);
  } catch (const CaseException& e) {
    return e.errors();
  }
}

RunOutput run_3d_point(const CaseSpec& spec, const RunControl& control, const CaseLimits& limits) {
  const auto t0 = Clock::now();
  // The limit counts the whole run, the mesh and the assembly included, as in 2D.
  const Deadline deadline = run_deadline(t0, spec.solver.time_limit_s);
  // Before anything is built: a builtin of many cells is refused at once.
  if (const auto unknowns = builtin_3d_unknowns(spec.mesh))
    check_size_of(*unknowns, false, spec, limits);
  TetMesh coarse = coarse_mesh(spec.mesh);
  check_size_of(tet_mesh_unknowns(coarse), true, spec, limits);
  CaseSpec used = spec;  // the case with the weights as used
  used.weights.length_scale = length_scale(coarse);
  // The coarse mesh's extent names a body too thin for double precision (indefinite_3d).
  const TetMesh coarse_for_messages = coarse;
  TetHierarchy meshes = build_tet_hierarchy(std::move(coarse), spec.mesh.refinements);
  deadline.check("refining the mesh");
  check_groups(spec, meshes.finest());
  const double mesh_s = seconds_since(t0);

  ProblemData<3> data = problem_data<3>(used, meshes.finest());
  choose_contact_weight<3>(used, meshes, data);  // as in 2D
  const CaseSolveObserver observer = solve_observer(control, deadline);
  // The one loop of both dimensions (adaptive_runner.hpp): a plain solve is its first step.
  CaseSolutionOf<3> solution;
  try {
    solution = solve_case_levels<3>(std::move(meshes), data, spec, observer, control.start);
  } catch (const NonFiniteError& e) {
    throw CaseException({non_finite_problem(e.what())});
  } catch (const IndefiniteSystemError& e) {
    throw indefinite_3d(used, coarse_for_messages, e.what());
  }

  RunOutput out;
  if (solution.report.cancelled) {
    out.cancelled = true;
    return out;
  }
  const Discretization<3>& disc = *solution.disc;
  out.result = case3d_result(used, disc, solution.x, solution.report);
  if (spec.adaptivity) out.result["adaptivity"] = adaptivity_json(solution, *spec.adaptivity);
  if (spec.accuracy) out.result["accuracy"] = accuracy_json(solution, *spec.accuracy);
  // Estimation and refinement between the solves of an adaptive run count as solving.
  const double total_s = seconds_since(t0);
  out.result["timing"] = {{"mesh_s", mesh_s},
                          {"assembly_s", solution.assembly_s},
                          {"solve_s", total_s - mesh_s - solution.assembly_s},
                          {"total_s", total_s}};
  if (control.want_vtu) {
    const FoslsAssembler<3>& a = disc.assembler();
    out.vtu = write_tet_vtu(a, disc.problem(), solution.full,
                            control.vtu_ascii ? VtuEncoding::kAscii : VtuEncoding::kBinary);
  }
  out.solution = std::move(solution.x);
  return out;
}

}  // namespace fosls
