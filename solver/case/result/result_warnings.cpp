#include "case/result/result_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "case/format/expression.hpp"

namespace fosls {

namespace {

using nlohmann::json;

std::string num(double v) { return sentence_number(v); }

std::string at(const Point& p) { return "(" + num(p.x()) + ", " + num(p.y()) + ")"; }

/// The case's condition of a mesh group, or null.
const BoundaryCondition* condition_of(const CaseSpec& spec, const Mesh& mesh, int group) {
  if (group < 0) return nullptr;
  const auto it = spec.boundary.find(mesh.group_names()[group]);
  return it == spec.boundary.end() ? nullptr : &it->second;
}

/// How far a point lies inside the obstacle where the case puts it, before the obstacle's
/// displacement (which is a prescribed indentation, not a mistake): > 0 inside.
double overlap(const Obstacle& o, const Point& p) {
  switch (o.kind) {
    case Obstacle::Kind::kPlane:
      return -(p - (o.point - o.displacement).head<2>()).dot(o.normal.head<2>());
    case Obstacle::Kind::kBall:
      return o.radius - (p - (o.center - o.displacement).head<2>()).norm();
    case Obstacle::Kind::kGap:
      break;
  }
  return -compile_scalar(o.gap)(p.x(), p.y());
}

/// A plane obstacle that no edge of its contact group faces: its normal points from the body
/// into the obstacle, so the constraint never applies (or, along the obstacle's normal, the
/// whole boundary starts inside it).
struct FacingAway {
  std::string group;
  Point normal;
};

struct ContactGeometry {
  std::vector<FacingAway> facing_away;
  int overlapping = 0, vertices = 0;
  double overlap = 0.0;  ///< the largest
  Point where = Point::Zero();
  std::string group;                                         ///< of the largest overlap
  double min_gap = std::numeric_limits<double>::infinity();  ///< remaining, after the solve
  Point min_gap_at = Point::Zero();
};

ContactGeometry contact_geometry(const CaseSpec& spec, const Mesh& mesh,
                                 const ContactResult& contact) {
  ContactGeometry g;
  std::map<int, bool> faces;  // plane group → some edge faces its plane
  for (const auto& e : contact.edges) {
    const int group = mesh.edge_group(e.edge);
    const BoundaryCondition* bc = condition_of(spec, mesh, group);
    if (bc && bc->obstacle.kind == Obstacle::Kind::kPlane)
      faces[group] |= mesh.edge_normal(e.edge).dot(bc->obstacle.normal.head<2>()) < 0.0;
  }
  for (const auto& [group, facing] : faces)
    if (!facing)
      g.facing_away.push_back(
          {mesh.group_names()[group], condition_of(spec, mesh, group)->obstacle.normal.head<2>()});
  // Overlaps below 1e-6 of the body's size are touching: a meshed arc's vertices lie on the
  // arc only to gmsh's tolerance (3e-7 on the robustness cases' annulus sector, a body of 2).
  const double tolerance = kTouchingOverlap * mesh.diameter();
  std::map<int, const BoundaryCondition*> vertex_condition;
  for (const auto& e : contact.edges) {
    const int group = mesh.edge_group(e.edge);
    if (faces.count(group) && !faces[group]) continue;  // reported as facing away
    for (int v : mesh.edge(e.edge)) vertex_condition[v] = condition_of(spec, mesh, group);
  }
  for (const auto& [v, bc] : vertex_condition) {
    if (!bc) continue;
    ++g.vertices;
    const double d = overlap(bc->obstacle, mesh.vertex(v));
    if (d <= tolerance) continue;
    ++g.overlapping;
    if (d > g.overlap) g.overlap = d, g.where = mesh.vertex(v);
  }
  for (const auto& r : contact.vertices)
    if (r.gap < g.min_gap) g.min_gap = r.gap, g.min_gap_at = mesh.vertex(r.vertex);
  return g;
}

ResultWarning facing_away_warning(const FacingAway& f) {
  const Point flipped = -f.normal + Point::Zero();  // +0, not -0, in the sentence
  return {"no_contact",
          "no contact: the plane obstacle of group '" + f.group + "' has the normal " +
              at(f.normal) +
              ", which points from the body into the obstacle: none of the group's edges faces "
              "it, so the contact constraint never applies and the force is 0. The normal must "
              "point from the obstacle into the body (here probably " +
              at(flipped) + ")",
          true};
}

ResultWarning no_contact_warning(const ContactGeometry& g, std::size_t edges) {
  std::string where =
      std::isfinite(g.min_gap)
          ? "the smallest remaining gap is " + num(g.min_gap) + " at " + at(g.min_gap_at) + ". "
          : "no contact vertex sees the obstacle along its constraint direction. ";
  return {"no_contact",
          "no contact: none of the " + std::to_string(edges) +
              " contact edges carries pressure, so the contact force is 0 and the result is the "
              "body without the obstacle; " +
              where +
              "Check that the load or displacement presses the body towards the obstacle (not "
              "away from it) and that the obstacle is where the case puts it",
          true};
}

ResultWarning overlap_warning(const ContactGeometry& g) {
  return {"initial_penetration",
          "the body starts inside the obstacle: " + std::to_string(g.overlapping) + " of " +
              std::to_string(g.vertices) + " contact vertices lie inside it, by up to " +
              num(g.overlap) + " at " + at(g.where) +
              " (before any obstacle displacement). The solver pushes the body out as if it had "
              "been pressed in by that much, so the force and pressure come from this overlap "
              "(an interference fit). If that is not intended, move the obstacle's point or "
              "center (an indentation belongs in the obstacle's displacement)",
          true};
}

ResultWarning resolution_warning(const ContactResult& contact, const ContactZone& z) {
  const double h = zone_end_edge_length(contact);
  return {"contact_zone_underresolved",
          "the contact zone is resolved by only " + std::to_string(z.edges) + " edges (they span " +
              num(z.length) + ", edges of about " + num(h) +
              " there): each end of the zone is known to about one edge, so the width only to "
              "about ±" +
              num(100.0 * h / z.length) +
              " % per end, and the peak pressure and the pressure's shape less well than the "
              "force. Refine the mesh near the contact (a smaller mesh.size there, more "
              "mesh.refinements, or an adaptivity section) until the zone spans at least " +
              std::to_string(kResolvedZoneEdges) + " edges",
          false};
}

}  // namespace

std::string sentence_number(double v, int digits) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

double zone_end_edge_length(const ContactResult& contact) {
  double ends = 0.0;  // the edges in contact next to one that is not: the contact fronts
  int n = 0;
  for (std::size_t i = 0; i < contact.edges.size(); ++i) {
    const bool active = contact.edges[i].active;
    const bool before = i > 0 && contact.edges[i - 1].active;
    const bool after = i + 1 < contact.edges.size() && contact.edges[i + 1].active;
    if (active && (!before || !after)) ends += contact.edges[i].length, ++n;
  }
  return n ? ends / n : 0.0;
}

std::vector<std::string> warning_codes() {
  return {"no_contact",
          "initial_penetration",
          "tangential_load_frictionless",
          "contact_zone_underresolved",
          "units_implausible",
          "large_strain",
          "not_converged",
          "time_limit",
          "rounding_level",
          "coarse_corrections_shortened",
          "coulomb_fallback",
          "roller_overrides_contact",
          "sweep_point_not_converged",
          "load_step_not_converged",
          "load_steps_partial",
          "accuracy_not_reached"};
}

void add_warnings(json& result, const std::vector<ResultWarning>& warnings) {
  if (!result.contains("warnings")) result["warnings"] = json::array();
  if (!result.contains("warning_details")) result["warning_details"] = json::array();
  bool review = result.value("review_required", false);
  for (const auto& w : warnings) {
    result["warnings"].push_back(w.message);
    result["warning_details"].push_back(
        {{"code", w.code}, {"message", w.message}, {"review", w.review}});
    review |= w.review;
  }
  result["review_required"] = review;
}

bool is_frictionless(const BoundaryCondition& condition) { return !condition.frictional(); }

std::optional<ResultWarning> large_strain_warning(double strain, double largest,
                                                  const Point& where) {
  if (!(strain > kLargeStrain)) return std::nullopt;
  return ResultWarning{
      "large_strain",
      "the equivalent strain exceeds " + num(100.0 * strain) +
          " % on 1 % of the body (the largest is " + num(100.0 * largest) + " % at " + at(where) +
          "): beyond a few per cent the small-deformation assumption of linear elasticity does "
          "not hold, and the answer is the linear one (no large rotations, no hyperelastic "
          "material). Check the load and the units; for larger strains use a nonlinear code",
      false};
}

std::vector<ResultWarning> contact_warnings(const CaseSpec& spec, const Mesh& finest,
                                            const ContactResult& contact) {
  std::vector<ResultWarning> out;
  if (contact.edges.empty()) return out;
  const ContactGeometry g = contact_geometry(spec, finest, contact);
  const ContactZone z = contact.zone();
  for (const auto& f : g.facing_away) out.push_back(facing_away_warning(f));
  if (z.edges == 0 && g.facing_away.empty())
    out.push_back(no_contact_warning(g, contact.edges.size()));
  if (g.overlapping > 0) out.push_back(overlap_warning(g));
  // A zone that ends only where the contact boundary ends (the whole boundary pressed) has no
  // front to resolve.
  bool front = false;
  for (std::size_t i = 0; i < contact.edges.size(); ++i)
    front |=
        contact.edges[i].active && ((i > 0 && !contact.edges[i - 1].active) ||
                                    (i + 1 < contact.edges.size() && !contact.edges[i + 1].active));
  if (front && z.edges < kResolvedZoneEdges) out.push_back(resolution_warning(contact, z));
  return out;
}

}  // namespace fosls
