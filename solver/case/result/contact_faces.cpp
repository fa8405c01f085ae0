// The contact output of a body whose contact boundary is a set of faces (3D): the force, the
// zone's area, extent and peak, and the warnings about it (contact_faces.hpp).

#include "case/result/contact_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "case/result/obstacle_gap.hpp"
#include "case/result/symmetry_planes.hpp"
#include "post/contact_force.hpp"
#include "post/contact_front.hpp"

namespace fosls {

namespace {

using nlohmann::json;

/// The smallest initial gap of a contact vertex along its face's normal, where, and the
/// obstacle it is measured to.
struct SmallestGap {
  double gap = std::numeric_limits<double>::infinity();
  Point3 at = Point3::Zero();
  const Obstacle* obstacle = nullptr;
};

/// `at_rest`: to the obstacles where the case puts them, before their displacement.
SmallestGap smallest_gap(const CaseSpec& spec, const TetMesh& mesh, bool at_rest) {
  SmallestGap out;
  std::map<std::string, ObstacleGap<3>> gaps;
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact)
      gaps.emplace(name, ObstacleGap<3>(bc.obstacle));
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.face_group(f) < 0) continue;  // an interior face
    const auto it = gaps.find(mesh.group_names()[mesh.face_group(f)]);
    if (it == gaps.end()) continue;
    const Obstacle& o = spec.boundary.at(it->first).obstacle;
    for (int v : mesh.face(f)) {
      const double g = at_rest ? it->second.at_rest(mesh.vertex(v), mesh.face_normal(f))
                               : it->second.along(mesh.vertex(v), mesh.face_normal(f));
      if (g < out.gap || !out.obstacle) out = {g, mesh.vertex(v), &o};
    }
  }
  return out;
}

/// What to move when the body starts inside an obstacle.
std::string move_hint(const Obstacle& o) {
  switch (o.kind) {
    case Obstacle::Kind::kPlane:
      return "Move the plane's point";
    case Obstacle::Kind::kBall:
      return "Move the sphere's center";
    default:
      return "Check the gap g";
  }
}

std::string where(const Point3& x) {
  return "(" + sentence_number(x.x()) + ", " + sentence_number(x.y()) + ", " +
         sentence_number(x.z()) + ")";
}

/// The radius of the disc of the whole zone's `area` (the modelled part's, mirrored across the
/// symmetry planes it lies against).
double whole_zone_radius(const FaceContact& c, double area) {
  return std::sqrt(std::ldexp(area, c.symmetry_planes) / M_PI);
}

/// 2D's contact_zone_underresolved for a zone that is a patch of faces: its diameter 2a, a the
/// radius of the disc of the whole zone's area, spans fewer than kResolvedZoneEdges face sizes
/// h (a face of area A has h = √(2A), a right triangle's leg). Only a zone with a front, not a
/// whole contact group in contact, whose edges the mesh gives exactly.
std::optional<ResultWarning> zone_resolution_warning(const FaceContact& c) {
  if (c.faces_in_contact == 0 || c.faces_in_contact == c.faces) return std::nullopt;
  const double radius = whole_zone_radius(c, c.area);
  const double h = std::sqrt(2.0 * c.area / c.faces_in_contact);
  const double across = 2.0 * radius / h;
  if (across >= kResolvedZoneEdges) return std::nullopt;
  return ResultWarning{
      "contact_zone_underresolved",
      "the contact zone is resolved by only " + std::to_string(c.faces_in_contact) +
          " faces: its diameter 2√(area/π) = " + sentence_number(2.0 * radius) +
          (c.symmetry_planes > 0 ? " (mirrored across the symmetry planes)" : "") +
          " spans about " + sentence_number(across, 2) + " faces of size " + sentence_number(h) +
          ", so its edge is known to about one face, the radius only to about ±" +
          sentence_number(100.0 * h / radius, 2) +
          " %, and the peak pressure less well than the force. Refine the mesh near the contact "
          "(a smaller mesh size there, more mesh.refinements) until it spans at least " +
          std::to_string(kResolvedZoneEdges) + " faces across",
      false};
}

/// The contact warnings 2D gives for the same findings, with the same codes; overlaps below
/// kTouchingOverlap of the body's size are touching, as in 2D.
std::vector<ResultWarning> zone_warnings(const CaseSpec& spec, const TetMesh& mesh,
                                         const FaceContact& c) {
  std::vector<ResultWarning> warnings;
  if (c.faces == 0) return warnings;
  // An overlap where the case puts the obstacle is a mistake; its displacement is not.
  const SmallestGap rest = smallest_gap(spec, mesh, true);
  const std::string noun = obstacle_noun(*rest.obstacle, 3);
  if (rest.gap < -kTouchingOverlap * mesh.diameter())
    warnings.push_back({"initial_penetration",
                        "the body starts inside the " + noun +
                            ": the gap along the body normal is down to " +
                            sentence_number(rest.gap) + " at " + where(rest.at) +
                            " (before any obstacle displacement); the solution pushes it out. " +
                            move_hint(*rest.obstacle) +
                            " if this is not meant (an indentation belongs in the obstacle's "
                            "displacement or the body's)",
                        true});
  if (auto w = zone_resolution_warning(c)) warnings.push_back(*w);
  if (c.faces_in_contact == 0) {
    const SmallestGap moved = smallest_gap(spec, mesh, false);
    warnings.push_back(
        {"no_contact",
         "nothing touches the " + noun + ": no contact face carries pressure and the force is 0; " +
             (std::isfinite(moved.gap)
                  ? "the smallest gap is " + sentence_number(moved.gap) + " at " + where(moved.at)
                  : "no contact vertex's outward normal meets it") +
             ". Press the body towards the " + noun,
         true});
  }
  return warnings;
}

/// Contact vertices whose obstacle constraint a roller displaced: the roller's axis was more
/// than 30° from the contact's tangent plane (roller_frame), so its data won and the vertex
/// may cross the obstacle. A documented rule, but the answer is not what the case says there.
std::vector<ResultWarning> roller_warnings(const FoslsSpace<3>& space) {
  const TetMesh& mesh = space.mesh();
  std::vector<char> seen(mesh.num_vertices(), 0);
  int count = 0;
  Point3 first = Point3::Zero();
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (!space.is_contact_facet(f)) continue;
    for (int v : mesh.face(f)) {
      if (seen[v] || space.is_contact_vertex(v)) continue;
      seen[v] = 1;
      bool held = true;  // by a full dirichlet group: its data win, as intended
      for (int c = 0; c < 3; ++c) held &= space.fixed(space.u_dof(v, c));
      if (held) continue;
      if (count++ == 0) first = mesh.vertex(v);
    }
  }
  if (count == 0) return {};
  return {{"roller_overrides_contact",
           std::to_string(count) + " contact vertices (the first at " + where(first) +
               ") lie on a roller whose prescribed axis is more than 30° from the contact's "
               "tangent plane: the roller's data win there and the obstacle does not hold "
               "them, so the body may cross it at those vertices. End the roller group before "
               "the contact zone, or prescribe the components a symmetry plane through the "
               "contact zone would (the one along its normal)",
           true}};
}

/// The zone's extent and peak (docs/result-format.md, "3D results"): its area within the located
/// front, the radius of the disc of the whole zone's area (Hertz's a), its bounding box, and
/// where the pressure peaks. Zeros and nulls without contact, as in 2D.
json zone_json(const FaceContact& c) {
  const bool touching = c.faces_in_contact > 0;
  const auto point = [touching](const Point3& x) {
    return touching ? json::array({x.x(), x.y(), x.z()}) : json(nullptr);
  };
  return {{"faces", c.faces_in_contact},
          {"area", c.front_area},
          {"symmetry_planes", c.symmetry_planes},
          {"radius", whole_zone_radius(c, c.front_area)},
          {"box_min", point(c.lo)},
          {"box_max", point(c.hi)},
          {"peak_pressure", c.max_pressure},
          {"peak_location", point(c.peak_at)}};
}

}  // namespace

FaceContact face_contact(const CaseSpec& spec, const Discretization<3>& disc,
                         const Vector& x_full) {
  const FoslsSpace<3>& space = disc.finest_space();
  const TetMesh& mesh = disc.meshes().finest();
  const double scale = disc.problem().stress_scale;
  const std::vector<double> p = contact_pressure(space, x_full, scale);
  FaceContact s;
  s.force = contact_force(space, x_full, scale);
  std::vector<int> contact_faces, loaded;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (!disc.finest_space().is_contact_facet(f)) continue;
    contact_faces.push_back(f);
    ++s.faces;
    if (p[f] > s.max_pressure) s.peak_at = mesh.face_centroid(f);
    s.max_pressure = std::max(s.max_pressure, p[f]);
    if (p[f] > 0) {
      loaded.push_back(f);
      s.area += mesh.face_area(f);
      ++s.faces_in_contact;
      for (int v : mesh.face(f)) {
        s.lo = s.lo.cwiseMin(mesh.vertex(v));
        s.hi = s.hi.cwiseMax(mesh.vertex(v));
      }
    }
  }
  const std::vector<MirrorPlane> planes = symmetry_planes(spec, mesh);
  s.front_area = area_within_front(mesh, contact_faces, p, planes);
  const std::vector<MirrorPlane> mirrors = planes_against(planes, mesh, loaded);
  s.symmetry_planes = static_cast<int>(mirrors.size());
  s.line = zone_line(mesh, contact_faces, p, s.force, mirrors);
  return s;
}

json face_contact_json(const FaceContact& c) {
  return {{"force", {c.force.x(), c.force.y(), c.force.z()}},
          {"max_pressure", c.max_pressure},
          {"area", c.area},
          {"faces", c.faces},
          {"faces_in_contact", c.faces_in_contact},
          {"zone", zone_json(c)},
          {"line", zone_line_json(c.line)}};
}

std::vector<ResultWarning> face_contact_warnings(const CaseSpec& spec, const FoslsSpace<3>& space,
                                                 const FaceContact& c) {
  std::vector<ResultWarning> warnings = zone_warnings(spec, space.mesh(), c);
  for (ResultWarning& w : roller_warnings(space)) warnings.push_back(std::move(w));
  return warnings;
}

}  // namespace fosls
