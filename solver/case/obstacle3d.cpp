// The gap of a 3D contact condition's rigid obstacle along the body normal (obstacle3d.hpp).

#include "case/obstacle3d.hpp"

#include <cmath>
#include <limits>

namespace fosls {

ObstacleGap3d::ObstacleGap3d(const Obstacle& obstacle) : obstacle_(obstacle) {
  if (obstacle.kind == Obstacle::Kind::kGap) gap_ = compile_scalar_3d(obstacle.gap);
}

double ObstacleGap3d::from(const Point3& x, const Point3& n, const Point3& shift) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Obstacle& o = obstacle_;
  switch (o.kind) {
    case Obstacle::Kind::kPlane: {
      const double approach = -n.dot(o.normal);  // how directly n points at the plane
      return (x - (o.point + shift)).dot(o.normal) / approach;
    }
    case Obstacle::Kind::kBall: {
      // The ray x + s n meets the sphere where s² + 2 b s + c = 0, c = |x − centre|² − R².
      const Point3 rel = x - (o.center + shift);
      const double b = n.dot(rel), c = rel.squaredNorm() - o.radius * o.radius;
      const double disc = b * b - c;
      if (disc < 0) return kInf;
      const double s = -b - std::sqrt(disc);
      // Inside (c < 0) the smaller root is negative: how far back along n the surface is, so
      // that moving the ball moves every gap along n alike. Outside, a ball behind is missed.
      if (c < 0) return s;
      return s >= 0 ? s : kInf;
    }
    case Obstacle::Kind::kGap:
      return gap_(x.x(), x.y(), x.z());
  }
  return kInf;
}

const char* obstacle_noun_3d(const Obstacle& o) {
  switch (o.kind) {
    case Obstacle::Kind::kPlane:
      return "plane";
    case Obstacle::Kind::kBall:
      return "sphere";
    default:
      return "obstacle";
  }
}

}  // namespace fosls
