// The element matrices of the displacement FEM reference (displacement_fem.cpp): plane strain,
// and axisymmetric about the y axis (x the radius r ≥ 0, y the axis z), whose integrals carry the
// weight 2πr so that a body of revolution's forces come out whole, as a 3D solve reports them.
#pragma once

#include <Eigen/Dense>
#include <array>

#include "mesh/mesh.hpp"

namespace fosls {

/// One P1 triangle's matrices: DOFs (x, y) of each vertex in turn; the pressure (mixed element)
/// linear on the triangle with the vertices' hat functions N_i.
struct ElementMatrices {
  Eigen::Matrix<double, 6, 6> stiffness;  ///< 2μ (ε(u), ε(v)), plus λ (div u, div v) if asked
  Eigen::Matrix<double, 3, 6> coupling;   ///< (N_i, div v_j)
  Eigen::Matrix3d mass;                   ///< (N_i, N_j)
  Eigen::Matrix<double, 6, 1> load;       ///< (f, v_j) for a constant body force f
};

struct ElementData {
  std::array<Point, 3> x;  ///< the vertices, counter-clockwise
  double mu = 1.0;
  double lambda_in_stiffness = 0.0;  ///< λ for the plain P1 element, 0 for the mixed one
  Point body_force = Point::Zero();
};

ElementMatrices plane_strain_element(const ElementData& e);
ElementMatrices axisymmetric_element(const ElementData& e);

/// ∫ N_i w ds over a boundary edge from a to b, i = a, b; w = 1 (plane) or 2πr (axisymmetric).
std::array<double, 2> edge_load_weights(const Point& a, const Point& b, bool axisymmetric);

}  // namespace fosls
