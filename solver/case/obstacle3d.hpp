#pragma once
// The gap of a 3D contact condition's rigid obstacle along the body normal: to a plane, to a
// sphere where the ray along the normal first meets it, or the gap function itself. (2D's gap is
// the assembly layer's RigidObstacle; the two meet in the one contact description of the unified
// finite-element stack.)

#include "case/case_spec.hpp"
#include "case/expression.hpp"

namespace fosls {

class ObstacleGap3d {
 public:
  /// A gap function is compiled once here.
  explicit ObstacleGap3d(const Obstacle& obstacle);
  /// The distance from x to the obstacle along the body's unit outward normal n there: the
  /// first hit of the ray x + s n (+∞ when it misses); where x is already inside the ball, the
  /// distance back along n to its sphere (negative).
  double along(const Point3& x, const Point3& n) const { return from(x, n, Point3::Zero()); }
  /// The same to the obstacle where the case puts it, before its displacement.
  double at_rest(const Point3& x, const Point3& n) const {
    return from(x, n, -obstacle_.displacement);
  }
  const Obstacle& obstacle() const { return obstacle_; }

 private:
  /// The gap with the plane or sphere moved by `shift`.
  double from(const Point3& x, const Point3& n, const Point3& shift) const;

  Obstacle obstacle_;
  ScalarFunction3d gap_;
};

/// "plane", "sphere" or "obstacle": the word for a 3D obstacle in messages.
const char* obstacle_noun_3d(const Obstacle& o);

}  // namespace fosls
