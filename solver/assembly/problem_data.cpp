#include "assembly/problem_data.hpp"

#include <cmath>
#include <limits>

namespace fosls {

ContactPoint locate_obstacle(const ContactData& c, const Point& p, const Point& n) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const RigidObstacle& o = c.obstacle;
  const bool along_body = c.direction == ConstraintDirection::kBodyNormal;
  switch (o.kind) {
    case RigidObstacle::Kind::kPlane: {
      const Point nu = o.normal.normalized();  // from the obstacle into the body
      const double height = (p - o.point).dot(nu);
      if (!along_body) return {-nu, height};
      const double approach = -n.dot(nu);  // how directly n points at the plane
      if (approach <= 1e-12) return {n, kInf};
      return {n, height / approach};
    }
    case RigidObstacle::Kind::kCircle: {
      const Point rel = p - o.center;
      const double dist = rel.norm();
      if (!along_body || dist < o.radius) {
        // Obstacle normal, or a point that already penetrates: the radial distance.
        Point nu = dist > 0 ? Point(rel / dist) : Point(-n);
        return {along_body ? n : Point(-nu), dist - o.radius};
      }
      // First hit of the ray p + s n with the circle.
      const double b = n.dot(rel);
      const double disc = b * b - (dist * dist - o.radius * o.radius);
      if (disc < 0) return {n, kInf};
      const double s = -b - std::sqrt(disc);
      return {n, s >= 0 ? s : kInf};
    }
    case RigidObstacle::Kind::kGap:
      return {n, c.gap(p.x(), p.y())};
  }
  return {n, kInf};
}

}  // namespace fosls
