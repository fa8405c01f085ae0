#pragma once
// The gap of a contact condition's rigid obstacle along the body normal, as the case states it:
// to a plane, to a sphere (a circle in 2D) where the ray along the normal first meets it, or the
// gap function itself; with the obstacle where the case puts it or moved by its displacement.
// For the result's warnings (an initial overlap, the smallest gap without contact); the
// assembly's constraint is assembly/contact_frame's.

#include "assembly/problem_data.hpp"
#include "case/format/case_spec.hpp"

namespace fosls {

template <int dim>
class ObstacleGap {
 public:
  /// A gap function is compiled once here.
  explicit ObstacleGap(const Obstacle& obstacle);
  /// The distance from x to the obstacle along the body's unit outward normal n there: the
  /// first hit of the ray x + s n (+∞ when it misses); where x is already inside the ball, the
  /// distance back along n to its surface (negative).
  double along(const Vec<dim>& x, const Vec<dim>& n) const { return from(x, n, Vec<dim>::Zero()); }
  /// The same to the obstacle where the case puts it, before its displacement.
  double at_rest(const Vec<dim>& x, const Vec<dim>& n) const {
    return from(x, n, -obstacle_.displacement.template head<dim>());
  }
  const Obstacle& obstacle() const { return obstacle_; }

 private:
  /// The gap with the plane or ball moved by `shift`.
  double from(const Vec<dim>& x, const Vec<dim>& n, const Vec<dim>& shift) const;

  Obstacle obstacle_;
  ScalarFunctionOf<dim> gap_;
};

/// "plane", "sphere" ("circle" in 2D) or "obstacle": the word for an obstacle in messages.
const char* obstacle_noun(const Obstacle& o, int dim);

}  // namespace fosls
