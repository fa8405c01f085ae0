#include "case/case3d_result.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fosls {

namespace {

using nlohmann::json;

struct ContactSummary {
  Point3 force = Point3::Zero();
  double max_pressure = 0.0;
  double area = 0.0;  ///< of the faces with p > 0
  int faces = 0;      ///< of the contact groups
  int faces_in_contact = 0;
};

ContactSummary contact_summary(const TetDiscretization& disc, const Vector& x_full) {
  const TetAssembler& a = disc.assembler();
  const TetMesh& mesh = disc.meshes().finest();
  const std::vector<double> p = a.contact_pressure(x_full);
  ContactSummary s;
  s.force = a.contact_force(x_full);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (!disc.finest_space().is_contact_face(f)) continue;
    ++s.faces;
    s.max_pressure = std::max(s.max_pressure, p[f]);
    if (p[f] > 0) {
      s.area += mesh.face_area(f);
      ++s.faces_in_contact;
    }
  }
  return s;
}

/// The smallest initial gap of a contact vertex along its face's normal, and where.
std::pair<double, Point3> smallest_gap(const Case3dSpec& spec, const TetMesh& mesh) {
  std::pair<double, Point3> out{std::numeric_limits<double>::infinity(), Point3::Zero()};
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.face_group(f) < 0) continue;  // an interior face
    const auto it = spec.boundary.find(mesh.group_names()[mesh.face_group(f)]);
    if (it == spec.boundary.end() || it->second.type != Condition3d::Type::kContact) continue;
    const Condition3d& c = it->second;
    for (int v : mesh.face(f)) {
      const double g = (mesh.vertex(v) - c.plane_point).dot(c.plane_normal) /
                       -mesh.face_normal(f).dot(c.plane_normal);
      if (g < out.first) out = {g, mesh.vertex(v)};
    }
  }
  return out;
}

std::string where(const Point3& x) {
  std::ostringstream s;
  s << "(" << x.x() << ", " << x.y() << ", " << x.z() << ")";
  return s.str();
}

json warnings(const Case3dSpec& spec, const TetMesh& mesh, const ContactSummary& c,
              const SolverReport& report) {
  json details = json::array();
  auto add = [&details](const char* code, const std::string& message, bool review) {
    details.push_back({{"code", code}, {"message", message}, {"review", review}});
  };
  const auto [gap, at] = smallest_gap(spec, mesh);
  const double size = (mesh.vertex(0) - at).norm() + 1.0;  // a scale for "touching"
  if (c.faces > 0 && gap < -1e-6 * size)
    add("initial_penetration",
        "the body starts inside the plane: the gap along the body normal is down to " +
            std::to_string(gap) + " at " + where(at) +
            "; the solution pushes it out. Move the plane's point if this is not meant",
        true);
  if (c.faces > 0 && c.faces_in_contact == 0)
    add("no_contact",
        "nothing touches the plane: no contact face carries pressure and the force is 0; the "
        "smallest gap is " +
            std::to_string(gap) + " at " + where(at) + ". Press the body towards the plane",
        true);
  if (!report.converged)
    add("not_converged",
        "the iteration stopped before the tolerance (" + report.message +
            "); the result is the last iterate",
        false);
  return details;
}

}  // namespace

json case3d_result(const Case3dSpec& spec, const TetDiscretization& disc, const Vector& x_free,
                   const SolverReport& report) {
  const TetAssembler& a = disc.assembler();
  const Vector x_full = a.full_vector(disc.problem(), x_free);
  const TetMesh& mesh = disc.meshes().finest();
  const ContactSummary c = contact_summary(disc, x_full);
  const FunctionalParts parts = a.functional(x_full);
  json r;
  r["name"] = spec.name;
  r["dimension"] = 3;
  r["converged"] = report.converged;
  r["iterations"] = report.iterations;
  r["method"] = spec.solver.method == SolverMethod::kPdas ? "pdas" : "mmg";
  r["tolerance"] = spec.solver.tolerance;
  r["relative_kkt_residual"] =
      report.initial_kkt > 0 ? report.final_kkt / report.initial_kkt : report.final_kkt;
  r["levels"] = disc.meshes().num_levels();
  r["dofs"] = disc.problem().qp.size();
  r["tetrahedra"] = mesh.num_tets();
  r["vertices"] = mesh.num_vertices();
  r["material"] = {
      {"mu", spec.material.mu},
      {"lambda", spec.material.incompressible() ? json("inf") : json(spec.material.lambda)}};
  r["functional"] = {{"total", parts.total()}, {"estimator", std::sqrt(parts.total())}};
  r["contact"] = {{"force", {c.force.x(), c.force.y(), c.force.z()}},
                  {"max_pressure", c.max_pressure},
                  {"area", c.area},
                  {"faces", c.faces},
                  {"faces_in_contact", c.faces_in_contact}};
  const json details = warnings(spec, mesh, c, report);
  r["warning_details"] = details;
  r["warnings"] = json::array();
  bool review = false;
  for (const auto& w : details) {
    r["warnings"].push_back(w["message"]);
    review = review || w["review"].get<bool>();
  }
  r["review_required"] = review;
  return r;
}

}  // namespace fosls
