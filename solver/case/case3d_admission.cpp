#include "case/case3d_admission.hpp"

#include <cmath>
#include <optional>
#include <sstream>
#include <variant>

#include "case/case3d_reader.hpp"
#include "case/early_group_check.hpp"
#include "case/job_time.hpp"
#include "case/memory_size.hpp"
#include "case/rigid_motions3d.hpp"
#include "case/solver_methods.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/tet_msh_reader.hpp"

namespace fosls {

namespace {

/// A builtin's coarse unknowns before it is built: Kuhn meshes have about T/6 vertices and 2T
/// faces for T tetrahedra, three unknowns each.
double builtin_coarse_unknowns(const Mesh3dSpec& m) {
  const double cubes =
      m.kind == Mesh3dSpec::Kind::kBox
          ? double(m.cells[0]) * m.cells[1] * m.cells[2]
          : (m.ball.quarter ? 1.0 : 4.0) * m.ball.cells * m.ball.cells * m.ball.cells;
  return 3.0 * (1.0 / 6.0 + 2.0) * 6.0 * cubes;
}

/// The text's mesh, or its problems at the mesh source's pointer.
std::variant<TetMesh, std::vector<CaseError>> msh_mesh(const Mesh3dSpec& m) {
  try {
    return tet_mesh_from_msh(m.msh_text);
  } catch (const MeshError& e) {
    std::vector<CaseError> errors;
    for (const auto& p : e.problems()) errors.push_back({mesh3d_source_pointer(m), p.detail});
    return errors;
  }
}

/// A budget's problem names the other method, with its figure, when that one fits the budget.
std::string other_method_advice(SolverMethod other, bool fits, const std::string& figure) {
  if (!fits) return "";
  return std::string(", or solver.method ") + method_info(other).name + " (about " + figure + ")";
}

}  // namespace

Case3dEstimate estimate_3d_solve(double unknowns, SolverMethod method) {
  Case3dEstimate e;
  e.unknowns = unknowns;
  // Memory: pdas's direct solver fills in, so its figure is the largest measured.
  const bool pdas = method == SolverMethod::kPdas;
  e.bytes = 40.0 * (1 << 20) + (pdas ? 8000.0 : 2200.0) * unknowns;
  // Time: the largest measured time per unknown with contact of each method (mmg: the
  // incompressible rounded punch of the robustness cases, an unstructured mesh with a large
  // contact zone; pdas: the Hertz ball at refinement 3 on a slower machine, that punch and the
  // incompressible block); pdas's grows with its
  // fill-in beyond the 6.4·10⁵ unknowns where it was measured.
  const double per_unknown = pdas ? 300e-6 * std::max(1.0, std::sqrt(unknowns / 6.4e5)) : 260e-6;
  e.seconds = 1.0 + per_unknown * unknowns;
  return e;
}

std::optional<double> builtin_3d_unknowns(const Mesh3dSpec& m) {
  if (m.kind == Mesh3dSpec::Kind::kBox || m.kind == Mesh3dSpec::Kind::kHalfBall)
    return builtin_coarse_unknowns(m);
  return std::nullopt;
}

int tet_group_index(const TetMesh& mesh, const std::string& name) { return mesh.group_index(name); }

namespace {

/// Where a function of x, y, z is not a number on a group: an expression was checked at three
/// sample points only, and a NaN would reach the solve (a gap would leave its vertex silently
/// unconstrained). Dirichlet data and gaps are evaluated at the group's vertices, tractions at
/// its faces' edge midpoints, as the assembly does.
std::optional<CaseError> check_finite_on_group(const std::string& name, const std::string& pointer,
                                               const std::string& what, const Component3d& fn,
                                               const TetMesh& mesh, const std::vector<int>& faces,
                                               bool midpoints) {
  for (int f : faces) {
    const auto& v = mesh.face(f);
    for (int k = 0; k < 3; ++k) {
      const Point3 x = midpoints ? Point3(0.5 * (mesh.vertex(v[k]) + mesh.vertex(v[(k + 1) % 3])))
                                 : mesh.vertex(v[k]);
      const double value = fn(x.x(), x.y(), x.z());
      if (std::isfinite(value)) continue;
      std::ostringstream s;
      s << what << " is not finite at (x, y, z) = (" << x.x() << ", " << x.y() << ", " << x.z()
        << ") (value " << value << "), a " << (midpoints ? "point" : "vertex") << " of the group "
        << name << "; it must give a number at every " << (midpoints ? "point" : "vertex")
        << " of the group";
      return CaseError{pointer, s.str()};
    }
  }
  return std::nullopt;
}

/// The expressions of a group's condition, checked on the group's `faces`.
void check_condition_values(const std::string& name, const Condition3d& bc, const TetMesh& mesh,
                            const std::vector<int>& faces, std::vector<CaseError>& errors) {
  const std::string at = child_pointer("/boundary", name);
  if (bc.type == Condition3d::Type::kContact) {
    if (bc.obstacle.kind != Obstacle3d::Kind::kGap) return;
    if (auto e = check_finite_on_group(name, child_pointer(child_pointer(at, "obstacle"), "g"),
                                       "the gap g", bc.obstacle.gap, mesh, faces, false))
      errors.push_back(*e);
    return;
  }
  if (bc.type == Condition3d::Type::kPressure) {
    if (auto e = check_finite_on_group(name, child_pointer(at, "pressure"), "the pressure",
                                       bc.values[0], mesh, faces, true))
      errors.push_back(*e);
    return;
  }
  const bool dirichlet = bc.type == Condition3d::Type::kDirichlet;
  const std::string field = dirichlet ? "displacement" : "traction";
  for (int c = 0; c < 3; ++c) {
    if (!bc.values[c]) continue;
    const std::string what = std::string("the ") + field + "'s " + "xyz"[c] + " component";
    if (auto e = check_finite_on_group(name, child_pointer(at, field) + "/" + std::to_string(c),
                                       what, bc.values[c], mesh, faces, !dirichlet)) {
      errors.push_back(*e);
      return;
    }
  }
}

/// Each group's faces in order, from one pass over the mesh: the checks below then cost the
/// faces once, not once per group (a case may name thousands).
std::vector<std::vector<int>> faces_by_group(const TetMesh& mesh) {
  std::vector<std::vector<int>> faces(mesh.group_names().size());
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (const int g = mesh.face_group(f); g >= 0) faces[g].push_back(f);
  return faces;
}

}  // namespace

std::vector<CaseError> check_3d_groups(const Case3dSpec& spec, const TetMesh& mesh) {
  std::vector<CaseError> errors;
  const std::vector<std::vector<int>> faces = faces_by_group(mesh);
  for (const auto& [name, bc] : spec.boundary) {
    const int g = tet_group_index(mesh, name);
    if (g < 0) {
      errors.push_back(unknown_group_problem(name, mesh.group_names()));
      continue;
    }
    check_condition_values(name, bc, mesh, faces[g], errors);
    if (bc.type != Condition3d::Type::kContact || bc.obstacle.kind == Obstacle3d::Kind::kGap)
      continue;
    // A plane's gap along a face's normal that does not point at it is infinite; a sphere's may
    // be, and the face is then unconstrained (as in 2D).
    if (bc.obstacle.kind != Obstacle3d::Kind::kPlane) continue;
    for (int f : faces[g]) {
      if (mesh.face_normal(f).dot(bc.obstacle.normal) < 0) continue;
      const Point3 c = mesh.face_centroid(f);
      std::ostringstream s;
      s << "the face of group " << name << " at (" << c.x() << ", " << c.y() << ", " << c.z()
        << ") does not face the plane (its outward normal is not against the plane's normal): "
           "the gap is measured along the body normal, so every face of a contact group must "
           "face the plane; check the normal's sign (from the plane into the body) or make the "
           "contact group smaller";
      const std::string at = child_pointer("/boundary", name);
      errors.push_back(
          {child_pointer(bc.obstacle.as_object ? child_pointer(at, "obstacle") : at, "normal"),
           s.str()});
      break;
    }
  }
  if (errors.empty())
    if (auto e = check_rigid_motions(spec, mesh)) errors.push_back(*e);
  return errors;
}

double tet_mesh_unknowns(const TetMesh& mesh) {
  return 3.0 * (mesh.num_vertices() + mesh.num_faces());
}

double finest_3d_unknowns(double coarse_unknowns, const Mesh3dSpec& mesh) {
  return coarse_unknowns * std::pow(8.0, mesh.refinements);
}

std::vector<CaseError> check_3d_size(double unknowns, const Case3dSpec& spec,
                                     const CaseLimits& limits) {
  const SolverMethod method = spec.solver.method;
  const Case3dEstimate e = estimate_3d_solve(unknowns, method);
  const std::string fix = "; use fewer refinements or a coarser mesh";
  const SolverMethod other =
      method == SolverMethod::kPdas ? SolverMethod::kMmg : SolverMethod::kPdas;
  const Case3dEstimate e_other = estimate_3d_solve(unknowns, other);
  std::ostringstream size;
  size << "about " << std::llround(unknowns) << " unknowns with " << method_info(method).name;
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
      << limits.memory_budget_name << fix
      << other_method_advice(other, e_other.bytes <= limits.max_memory_bytes,
                             format_bytes(e_other.bytes));
    errors.push_back({"/mesh/refinements", s.str()});
  }
  if (limits.max_seconds > 0 && e.seconds > limits.max_seconds) {
    std::ostringstream s;
    s << "the case needs about " << budget_text(std::ceil(e.seconds)) << " (" << size.str()
      << "), more than the " << budget_text(limits.max_seconds) << " " << limits.time_budget_name
      << fix
      << other_method_advice(other, e_other.seconds <= limits.max_seconds,
                             budget_text(std::ceil(e_other.seconds)));
    errors.push_back({"/mesh/refinements", s.str()});
  }
  return errors;
}

Case3dAdmission admit_case_3d(const nlohmann::json& j, const CaseReadOptions& options) {
  Case3dAdmission admission;
  Case3dReadResult read = read_case_3d(j, options);
  admission.errors = std::move(read.errors);
  if (!read.spec) return admission;
  const Case3dSpec& spec = *read.spec;
  std::optional<double> coarse = builtin_3d_unknowns(spec.mesh);
  if (spec.mesh.kind == Mesh3dSpec::Kind::kMsh) {  // read now: its problems are the case's
    auto mesh = msh_mesh(spec.mesh);
    if (auto* errors = std::get_if<std::vector<CaseError>>(&mesh)) {
      admission.errors = std::move(*errors);
      return admission;
    }
    const TetMesh& m = std::get<TetMesh>(mesh);
    admission.errors = check_3d_groups(spec, m);
    if (!admission.errors.empty()) return admission;
    coarse = tet_mesh_unknowns(m);
  }
  if (coarse) {
    admission.estimate =
        estimate_3d_solve(finest_3d_unknowns(*coarse, spec.mesh), spec.solver.method);
    admission.errors = check_3d_size(admission.estimate->unknowns, spec, options.limits);
  }
  admission.spec = std::move(read.spec);
  return admission;
}

}  // namespace fosls
