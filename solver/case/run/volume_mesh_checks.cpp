#include "case/run/volume_mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <variant>

#include "case/admission/early_group_check.hpp"
#include "case/format/expression.hpp"
#include "case/run/mesh_factory.hpp"
#include "case/run/rigid_motions.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/tet_half_ball.hpp"
#include "mesh/tet_msh_reader.hpp"
#include "mesh/tet_refinement.hpp"

namespace fosls {

namespace {

/// A builtin's coarse unknowns before it is built: Kuhn meshes have about T/6 vertices and 2T
/// faces for T tetrahedra, three unknowns each.
double builtin_coarse_unknowns(const MeshSpec& m) {
  const HalfBallSpec& ball = m.half_ball;
  const double cubes = m.builtin == "box"
                           ? double(m.box_cells[0]) * m.box_cells[1] * m.box_cells[2]
                           : (ball.quarter ? 1.0 : 4.0) * ball.cells * ball.cells * ball.cells;
  return 3.0 * (1.0 / 6.0 + 2.0) * 6.0 * cubes;
}

/// The text's mesh, or its problems at the mesh source's pointer.
std::variant<TetMesh, std::vector<CaseError>> msh_mesh(const MeshSpec& m) {
  try {
    return tet_mesh_from_msh(m.msh_text);
  } catch (const MeshError& e) {
    std::vector<CaseError> errors;
    for (const auto& p : e.problems()) errors.push_back({mesh_source_pointer(m), p.detail});
    return errors;
  }
}

/// Builtins up to this many coarse unknowns are built at admission (a fraction of a second), so
/// that what their parameters alone decide — a grading that folds a tetrahedron, dirichlet groups
/// that leave a rigid motion — is refused before the job is queued.
constexpr double kBuiltAtAdmission = 200000;

}  // namespace

std::variant<TetMesh, std::vector<CaseError>> builtin_3d_mesh(const MeshSpec& m) {
  try {
    return m.builtin == "box" ? make_box(m.box_cells, m.box_lengths) : make_half_ball(m.half_ball);
  } catch (const std::invalid_argument& e) {  // the half ball's grading folds a tetrahedron
    return std::vector<CaseError>{
        {mesh_source_pointer(m), std::string("these parameters give no valid mesh (") + e.what() +
                                     "); use a smaller grading or fewer cells"}};
  }
}

std::optional<double> builtin_3d_unknowns(const MeshSpec& m) {
  if (m.kind == MeshSpec::Kind::kBuiltin) return builtin_coarse_unknowns(m);
  return std::nullopt;
}

int tet_group_index(const TetMesh& mesh, const std::string& name) { return mesh.group_index(name); }

namespace {

/// Where a function of x, y, z is not a number on a group: an expression was checked at three
/// sample points only, and a NaN would reach the solve (a gap would leave its vertex silently
/// unconstrained). Dirichlet data and gaps are evaluated at the group's vertices, tractions at
/// its faces' edge midpoints, as the assembly does.
std::optional<CaseError> check_finite_on_group(const std::string& name, const std::string& pointer,
                                               const std::string& what, const ScalarFunction3d& fn,
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
void check_condition_values(const std::string& name, const BoundaryCondition& bc,
                            const TetMesh& mesh, const std::vector<int>& faces,
                            std::vector<CaseError>& errors) {
  const std::string at = child_pointer("/boundary", name);
  if (bc.type == BoundaryCondition::Type::kContact) {
    if (bc.obstacle.kind != Obstacle::Kind::kGap) return;
    if (auto e = check_finite_on_group(name, child_pointer(child_pointer(at, "obstacle"), "g"),
                                       "the gap g", compile_scalar_3d(bc.obstacle.gap), mesh, faces,
                                       false))
      errors.push_back(*e);
    return;
  }
  if (bc.type == BoundaryCondition::Type::kPressure) {
    if (auto e = check_finite_on_group(name, child_pointer(at, "pressure"), "the pressure",
                                       compile_scalar_3d(bc.values[0]), mesh, faces, true))
      errors.push_back(*e);
    return;
  }
  const bool dirichlet = bc.type == BoundaryCondition::Type::kDirichlet;
  const std::string field = dirichlet ? "displacement" : "traction";
  for (int c = 0; c < 3; ++c) {
    if (dirichlet && !bc.prescribed[c]) continue;
    const std::string what = std::string("the ") + field + "'s " + "xyz"[c] + " component";
    if (auto e =
            check_finite_on_group(name, child_pointer(at, field) + "/" + std::to_string(c), what,
                                  compile_scalar_3d(bc.values[c]), mesh, faces, !dirichlet)) {
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

std::vector<CaseError> check_3d_groups(const CaseSpec& spec, const TetMesh& mesh) {
  std::vector<CaseError> errors;
  const std::vector<std::vector<int>> faces = faces_by_group(mesh);
  for (const auto& [name, bc] : spec.boundary) {
    const int g = tet_group_index(mesh, name);
    if (g < 0) {
      errors.push_back(unknown_group_problem(name, mesh.group_names()));
      continue;
    }
    check_condition_values(name, bc, mesh, faces[g], errors);
    if (bc.type != BoundaryCondition::Type::kContact || bc.obstacle.kind == Obstacle::Kind::kGap)
      continue;
    // A plane's gap along a face's normal that does not point at it is infinite; a sphere's may
    // be, and the face is then unconstrained (as in 2D).
    if (bc.obstacle.kind != Obstacle::Kind::kPlane) continue;
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
          {child_pointer(bc.obstacle.short_form ? at : child_pointer(at, "obstacle"), "normal"),
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

double finest_3d_unknowns(double coarse_unknowns, int refinements) {
  return coarse_unknowns * std::pow(8.0, refinements);
}

Mesh3dCount count_3d_mesh(const CaseSpec& spec) {
  Mesh3dCount out;
  const MeshSpec& m = spec.mesh;
  std::optional<double> coarse = builtin_3d_unknowns(m);
  bool exact = false;
  if (m.kind == MeshSpec::Kind::kMsh) {  // read now: its problems are the case's
    auto mesh = msh_mesh(m);
    if (auto* errors = std::get_if<std::vector<CaseError>>(&mesh)) {
      out.errors = std::move(*errors);
      return out;
    }
    const TetMesh& built = std::get<TetMesh>(mesh);
    out.errors = check_3d_groups(spec, built);
    coarse = tet_mesh_unknowns(built);
    exact = true;
  } else if (coarse && *coarse <= kBuiltAtAdmission) {
    auto mesh = builtin_3d_mesh(m);
    if (auto* errors = std::get_if<std::vector<CaseError>>(&mesh)) {
      out.errors = std::move(*errors);
      return out;
    }
    out.errors = check_3d_groups(spec, std::get<TetMesh>(mesh));
  }
  if (coarse)
    out.count = ProblemCount{std::llround(finest_3d_unknowns(*coarse, m.refinements)),
                             std::llround(*coarse), exact, m.order, 3};
  return out;
}

}  // namespace fosls
