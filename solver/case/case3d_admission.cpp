#include "case/case3d_admission.hpp"

#include <cmath>
#include <sstream>

#include "case/case3d_reader.hpp"
#include "case/job_time.hpp"
#include "case/memory_size.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/tet_msh_reader.hpp"

namespace fosls {

namespace {

/// A builtin's coarse unknowns before it is built: Kuhn meshes have about T/6 vertices and 2T
/// faces for T tetrahedra, three unknowns each.
double builtin_coarse_unknowns(const Mesh3dSpec& m) {
  const double cubes = m.kind == Mesh3dSpec::Kind::kBox
                           ? double(m.cells[0]) * m.cells[1] * m.cells[2]
                           : 4.0 * m.ball.cells * m.ball.cells * m.ball.cells;
  return 3.0 * (1.0 / 6.0 + 2.0) * 6.0 * cubes;
}

/// The coarse unknowns of a mesh given as msh text, counted on the mesh (its problems are the
/// runner's to report, with the same reader: nothing is known here then).
std::optional<double> msh_coarse_unknowns(const std::string& text) {
  try {
    const TetMesh mesh = tet_mesh_from_msh(text);
    return 3.0 * (mesh.num_vertices() + mesh.num_faces());
  } catch (const MeshError&) {
    return std::nullopt;
  }
}

std::string method_name(SolverMethod method) {
  return method == SolverMethod::kPdas ? "pdas" : "mmg";
}

}  // namespace

Case3dEstimate estimate_3d_solve(double unknowns, SolverMethod method) {
  Case3dEstimate e;
  e.unknowns = unknowns;
  // Memory: pdas's direct solver fills in, so its figure is the largest measured.
  const bool pdas = method == SolverMethod::kPdas;
  e.bytes = 40.0 * (1 << 20) + (pdas ? 8000.0 : 2200.0) * unknowns;
  // Time: mmg's largest measured time per unknown with contact (the incompressible rounded
  // punch of the robustness cases, an unstructured mesh with a large contact zone); pdas's grows
  // with its fill-in beyond the 1.6·10⁵ unknowns where it was measured.
  const double per_unknown = pdas ? 90e-6 * std::max(1.0, std::sqrt(unknowns / 1.6e5)) : 260e-6;
  e.seconds = 1.0 + per_unknown * unknowns;
  return e;
}

std::optional<double> coarse_3d_unknowns(const Mesh3dSpec& m) {
  switch (m.kind) {
    case Mesh3dSpec::Kind::kBox:
    case Mesh3dSpec::Kind::kHalfBall:
      return builtin_coarse_unknowns(m);
    case Mesh3dSpec::Kind::kMsh:
      return msh_coarse_unknowns(m.msh_text);
    case Mesh3dSpec::Kind::kGeoFile:
      break;
  }
  return std::nullopt;
}

double finest_3d_unknowns(double coarse_unknowns, const Mesh3dSpec& mesh) {
  return coarse_unknowns * std::pow(8.0, mesh.refinements);
}

std::vector<CaseError> check_3d_size(double unknowns, const Case3dSpec& spec,
                                     const CaseLimits& limits) {
  const SolverMethod method = spec.solver.method;
  const Case3dEstimate e = estimate_3d_solve(unknowns, method);
  const std::string fix = "; use fewer refinements or a coarser mesh";
  const std::string mmg_too = method == SolverMethod::kPdas ? ", or solver.method mmg" : "";
  std::ostringstream size;
  size << "about " << std::llround(unknowns) << " unknowns with " << method_name(method);
  std::vector<CaseError> errors;
  if (unknowns > static_cast<double>(limits.max_dofs)) {
    std::ostringstream s;
    s << "this mesh and these refinements would give about " << std::llround(unknowns)
      << " unknowns, more than the limit of " << limits.max_dofs << fix;
    errors.push_back({"/mesh/refinements", s.str()});
    return errors;
  }
  if (limits.max_memory_bytes > 0 && e.bytes > limits.max_memory_bytes) {
    std::ostringstream s;
    s << "the solve needs about " << format_bytes(e.bytes) << " (" << size.str()
      << "), more than the " << format_bytes(limits.max_memory_bytes) << " "
      << limits.memory_budget_name << fix;
    if (!mmg_too.empty())
      s << mmg_too << " (about "
        << format_bytes(estimate_3d_solve(unknowns, SolverMethod::kMmg).bytes) << ")";
    errors.push_back({"/mesh/refinements", s.str()});
  }
  if (limits.max_seconds > 0 && e.seconds > limits.max_seconds) {
    std::ostringstream s;
    s << "the case needs about " << budget_text(std::ceil(e.seconds)) << " (" << size.str()
      << "), more than the " << budget_text(limits.max_seconds) << " " << limits.time_budget_name
      << fix << mmg_too;
    errors.push_back({"/mesh/refinements", s.str()});
  }
  return errors;
}

Case3dAdmission admit_case_3d(const nlohmann::json& j, const CaseReadOptions& options) {
  Case3dAdmission admission;
  Case3dReadResult read = read_case_3d(j, options);
  admission.errors = std::move(read.errors);
  if (!read.spec) return admission;
  if (const auto coarse = coarse_3d_unknowns(read.spec->mesh)) {
    admission.estimate =
        estimate_3d_solve(finest_3d_unknowns(*coarse, read.spec->mesh), read.spec->solver.method);
    admission.errors = check_3d_size(admission.estimate->unknowns, *read.spec, options.limits);
  }
  admission.spec = std::move(read.spec);
  return admission;
}

}  // namespace fosls
