#pragma once
// The line of the 3D result's pressure profile (`contact.line`, docs/result-format.md "3D
// results"): through the zone's centre of pressure along the first tangent axis, in the plane
// of the contact's normal. A model cut at symmetry planes is completed by its mirror images
// first, so a quarter ball's line runs through the pole along x, as the whole ball's does.

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "post/contact_front.hpp"
#include "post/pressure_section.hpp"

namespace fosls {

struct ZoneLine {
  Point3 point = Point3::Zero();       ///< the centre of pressure, s = 0
  Point3 direction = Point3::UnitX();  ///< unit, normal to `normal`
  Point3 normal = Point3::UnitZ();     ///< the contact force's direction
  std::vector<SectionStep> steps;
};

/// The line through the loaded faces of `faces` (none without one): the contact's normal is
/// the direction of `force` and the centre is the pressure's, both with the mirror images
/// across `mirrors` (the symmetry planes the zone lies against); the direction is x's part
/// normal to it (y's where x is nearly normal).
std::optional<ZoneLine> zone_line(const TetMesh& mesh, const std::vector<int>& faces,
                                  const std::vector<double>& pressure, const Point3& force,
                                  const std::vector<MirrorPlane>& mirrors);

/// `contact.line`: point, direction, and the steps as arrays from, to, pressure; null without a
/// line.
nlohmann::json zone_line_json(const std::optional<ZoneLine>& line);

}  // namespace fosls
