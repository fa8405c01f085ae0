#include "fem/contact_frame.hpp"

#include <Eigen/Geometry>

namespace fosls {

template <>
Mat<2> normal_frame<2>(const Point& n) {
  Mat<2> q;
  q << n.x(), -n.y(), n.y(), n.x();  // columns n, t
  return q;
}

template <>
Mat<3> normal_frame<3>(const Point3& n) {
  int axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  const Point3 t1 = n.cross(Point3::Unit(axis)).normalized();
  Mat<3> q;
  q.col(0) = n;
  q.col(1) = t1;
  q.col(2) = n.cross(t1);
  return q;
}

template <int dim>
Mat<dim> roller_frame(const Vec<dim>& normal, int prescribed) {
  Vec<dim> n = normal;
  int first = -1;
  for (int c = 0; c < dim; ++c)
    if (prescribed & (1 << c)) {
      n[c] = 0.0;
      if (first < 0) first = c;
    }
  if (first < 0) return normal_frame<dim>(normal);
  if (n.norm() < kRollerCosine * normal.norm()) return Mat<dim>::Zero();
  n.normalize();
  if constexpr (dim == 2) {
    return normal_frame<2>(n);  // t = (−n_y, n_x) is ± the prescribed axis
  } else {
    Mat<3> q;
    q.col(0) = n;
    q.col(1) = Point3::Unit(first);
    q.col(2) = n.cross(q.col(1));
    return q;
  }
}

template Mat<2> roller_frame<2>(const Point&, int);
template Mat<3> roller_frame<3>(const Point3&, int);

}  // namespace fosls
