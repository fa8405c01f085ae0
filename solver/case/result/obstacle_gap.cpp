// The gap of a contact condition's rigid obstacle along the body normal (obstacle_gap.hpp).

#include "case/result/obstacle_gap.hpp"

#include <cmath>
#include <limits>

#include "case/format/expression.hpp"

namespace fosls {

template <int dim>
ObstacleGap<dim>::ObstacleGap(const Obstacle& obstacle) : obstacle_(obstacle) {
  if (obstacle.kind != Obstacle::Kind::kGap) return;
  if constexpr (dim == 2)
    gap_ = compile_scalar(obstacle.gap);
  else
    gap_ = compile_scalar_3d(obstacle.gap);
}

template <int dim>
double ObstacleGap<dim>::from(const Vec<dim>& x, const Vec<dim>& n, const Vec<dim>& shift) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Obstacle& o = obstacle_;
  switch (o.kind) {
    case Obstacle::Kind::kPlane: {
      const Vec<dim> normal = o.normal.template head<dim>();
      const double approach = -n.dot(normal);  // how directly n points at the plane
      return (x - (o.point.template head<dim>() + shift)).dot(normal) / approach;
    }
    case Obstacle::Kind::kBall: {
      // The ray x + s n meets the sphere where s² + 2 b s + c = 0, c = |x − centre|² − R².
      const Vec<dim> rel = x - (o.center.template head<dim>() + shift);
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
      return evaluate<dim>(gap_, x);
  }
  return kInf;
}

const char* obstacle_noun(const Obstacle& o, int dim) {
  switch (o.kind) {
    case Obstacle::Kind::kPlane:
      return "plane";
    case Obstacle::Kind::kBall:
      return dim == 3 ? "sphere" : "circle";
    default:
      return "obstacle";
  }
}

template class ObstacleGap<2>;
template class ObstacleGap<3>;

}  // namespace fosls
