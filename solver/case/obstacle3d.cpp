// The gap of a 3D contact condition's rigid obstacle along the body normal (case3d_spec.hpp).

#include <cmath>
#include <limits>

#include "case/case3d_spec.hpp"

namespace fosls {

double Obstacle3d::gap_along(const Point3& x, const Point3& n) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  switch (kind) {
    case Kind::kPlane: {
      const double approach = -n.dot(normal);  // how directly n points at the plane
      return (x - point).dot(normal) / approach;
    }
    case Kind::kSphere: {
      const Point3 rel = x - center;
      const double dist = rel.norm();
      if (dist < radius) return dist - radius;  // already inside: how deep, radially
      // First hit of the ray x + s n with the sphere: s² + 2 b s + (|rel|² − R²) = 0.
      const double b = n.dot(rel);
      const double disc = b * b - (dist * dist - radius * radius);
      if (disc < 0) return kInf;
      const double s = -b - std::sqrt(disc);
      return s >= 0 ? s : kInf;
    }
    case Kind::kGap:
      return gap(x.x(), x.y(), x.z());
  }
  return kInf;
}

const char* Obstacle3d::noun() const {
  switch (kind) {
    case Kind::kPlane:
      return "plane";
    case Kind::kSphere:
      return "sphere";
    default:
      return "obstacle";
  }
}

}  // namespace fosls
