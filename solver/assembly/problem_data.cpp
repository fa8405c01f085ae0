#include "assembly/problem_data.hpp"

#include <cmath>
#include <limits>

namespace fosls {

template <int dim>
ContactPoint<dim> locate_obstacle(const ContactData<dim>& c, const Vec<dim>& p, const Vec<dim>& n) {
  return locate_obstacle<dim>(c, p, n, c.direction);
}

template <int dim>
ContactPoint<dim> locate_obstacle(const ContactData<dim>& c, const Vec<dim>& p, const Vec<dim>& n,
                                  ConstraintDirection direction) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  using Kind = typename RigidObstacle<dim>::Kind;
  const RigidObstacle<dim>& o = c.obstacle;
  const bool along_body = direction == ConstraintDirection::kBodyNormal;
  switch (o.kind) {
    case Kind::kPlane: {
      const Vec<dim>& nu = o.normal;  // from the obstacle into the body
      const double height = (p - o.point).dot(nu);
      if (!along_body) return {-nu, height};
      const double approach = -n.dot(nu);  // how directly n points at the plane
      if (approach <= 1e-12) return {n, kInf};
      return {n, height / approach};
    }
    case Kind::kBall: {
      const Vec<dim> rel = p - o.center;
      const double dist = rel.norm();
      if (!along_body) {  // the radial distance, along the obstacle's normal there
        const Vec<dim> nu = dist > 0 ? Vec<dim>(rel / dist) : Vec<dim>(-n);
        return {-nu, dist - o.radius};
      }
      // The ray p + s n meets the sphere where s² + 2 b s + dist² − R² = 0.
      const double b = n.dot(rel);
      const double disc = b * b - (dist * dist - o.radius * o.radius);
      if (dist < o.radius) {
        // Already inside the ball. 3D: the distance back along n to its sphere, so that moving
        // the ball moves every gap along n alike. 2D keeps its radial distance (its results
        // stay bit for bit; the two agree to second order where the normals meet the ball
        // head on).
        if constexpr (dim == 2)
          return {n, dist - o.radius};
        else
          return {n, -b - std::sqrt(disc)};
      }
      if (disc < 0) return {n, kInf};
      const double s = -b - std::sqrt(disc);  // the first hit; a ball behind p is missed
      return {n, s >= 0 ? s : kInf};
    }
    case Kind::kGap:
      return {n, evaluate<dim>(c.gap, p)};
  }
  return {n, kInf};
}

double capped_gap(double gap, double body_diameter) {
  const double far = 10.0 * body_diameter;
  return !std::isfinite(gap) || gap > far ? far : gap;
}

template <int dim>
std::vector<Vec<dim>> obstacle_vertex_normals(const SimplexMesh<dim>& mesh,
                                              const ProblemData<dim>& data) {
  bool any = false;
  for (const auto& g : data.groups)
    any |= g.role == GroupRole::kContact &&
           g.contact.direction == ConstraintDirection::kObstacleNormal;
  if (!any) return {};
  std::vector<Vec<dim>> averaged(mesh.num_vertices(), Vec<dim>::Zero());
  std::vector<int> group(mesh.num_vertices(), -1);
  for (int f = 0; f < mesh.num_facets(); ++f) {
    const int g = mesh.facet_group(f);
    if (g < 0 || data.groups[g].role != GroupRole::kContact) continue;
    for (int v : mesh.facet(f)) {
      averaged[v] += mesh.facet_normal(f);
      group[v] = g;
    }
  }
  std::vector<Vec<dim>> normals(mesh.num_vertices(), Vec<dim>::Zero());
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (group[v] < 0) continue;
    const Vec<dim> n = averaged[v].normalized();
    normals[v] = locate_obstacle<dim>(data.groups[group[v]].contact, mesh.vertex(v), n).direction;
  }
  return normals;
}

template ContactPoint<2> locate_obstacle<2>(const ContactData<2>&, const Point&, const Point&);
template ContactPoint<3> locate_obstacle<3>(const ContactData<3>&, const Point3&, const Point3&);
template ContactPoint<2> locate_obstacle<2>(const ContactData<2>&, const Point&, const Point&,
                                            ConstraintDirection);
template ContactPoint<3> locate_obstacle<3>(const ContactData<3>&, const Point3&, const Point3&,
                                            ConstraintDirection);
template std::vector<Point> obstacle_vertex_normals<2>(const Mesh&, const ProblemData<2>&);
template std::vector<Point3> obstacle_vertex_normals<3>(const TetMesh&, const ProblemData<3>&);

}  // namespace fosls
