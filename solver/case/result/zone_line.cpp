#include "case/result/zone_line.hpp"

#include <cmath>

namespace fosls {

namespace {

/// x less its part along `normal`, or y's when x is within about 8° of it.
Point3 first_tangent(const Point3& normal) {
  const Point3 axis = std::abs(normal.x()) < 0.99 ? Point3::UnitX() : Point3::UnitY();
  return (axis - axis.dot(normal) * normal).normalized();
}

/// `x` with its component along each mirror's normal taken to the plane: the point of the whole
/// (mirrored) zone that x stands for, or, for a direction (`through_origin`), its mirrored sum.
Point3 mirrored(Point3 x, const std::vector<MirrorPlane>& mirrors, bool through_origin) {
  for (const MirrorPlane& m : mirrors) {
    const Point3 from = through_origin ? Point3::Zero() : m.point;
    x -= (x - from).dot(m.normal) * m.normal;
  }
  return x;
}

}  // namespace

std::optional<ZoneLine> zone_line(const TetMesh& mesh, const std::vector<int>& faces,
                                  const std::vector<double>& pressure, const Point3& force,
                                  const std::vector<MirrorPlane>& mirrors) {
  Point3 moment = Point3::Zero();
  double load = 0.0;
  for (int f : faces) {
    if (!(pressure[f] > 0)) continue;
    load += pressure[f] * mesh.face_area(f);
    moment += pressure[f] * mesh.face_area(f) * mesh.face_centroid(f);
  }
  const Point3 normal = mirrored(force, mirrors, true);
  if (!(load > 0) || !(normal.norm() > 0)) return std::nullopt;
  ZoneLine line;
  line.normal = normal.normalized();
  line.point = mirrored(moment / load, mirrors, false);
  line.direction = first_tangent(line.normal);
  line.steps = pressure_section(mesh, faces, pressure, line.point, line.direction, line.normal);
  return line;
}

nlohmann::json zone_line_json(const std::optional<ZoneLine>& line) {
  if (!line) return nullptr;
  nlohmann::json from = nlohmann::json::array(), to = nlohmann::json::array(),
                 p = nlohmann::json::array();
  for (const SectionStep& s : line->steps) {
    from.push_back(s.from);
    to.push_back(s.to);
    p.push_back(s.pressure);
  }
  const auto point = [](const Point3& x) { return nlohmann::json::array({x.x(), x.y(), x.z()}); };
  return {{"point", point(line->point)},
          {"direction", point(line->direction)},
          {"from", from},
          {"to", to},
          {"pressure", p}};
}

}  // namespace fosls
