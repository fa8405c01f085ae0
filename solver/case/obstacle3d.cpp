// The gap of a 3D contact condition's rigid obstacle along the body normal (case3d_spec.hpp).

#include <cmath>
#include <limits>

#include "case/case3d_spec.hpp"

namespace fosls {

double Obstacle3d::gap_from(const Point3& x, const Point3& n, const Point3& shift) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  switch (kind) {
    case Kind::kPlane: {
      const double approach = -n.dot(normal);  // how directly n points at the plane
      return (x - (point + shift)).dot(normal) / approach;
    }
    case Kind::kSphere: {
      // The ray x + s n meets the sphere where s² + 2 b s + c = 0, c = |x − centre|² − R².
      const Point3 rel = x - (center + shift);
      const double b = n.dot(rel), c = rel.squaredNorm() - radius * radius;
      const double disc = b * b - c;
      if (disc < 0) return kInf;
      const double s = -b - std::sqrt(disc);
      // Inside (c < 0) the smaller root is negative: how far back along n the surface is, so
      // that moving the ball moves every gap along n alike. Outside, a ball behind is missed.
      if (c < 0) return s;
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
