#include "case/run/rigid_motions.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>
#include <vector>

namespace fosls {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

/// A motion's description: its translation or the axis of its rotation, rounded for reading.
std::string describe_motion(const Vector6& m, const Point3& centre) {
  std::ostringstream s;
  s.precision(3);
  const Point3 translation = m.head<3>(), rotation = m.tail<3>();
  auto direction = [&s](const Point3& d) {
    const Point3 u = d.normalized();
    for (int c = 0; c < 3; ++c)
      if (std::abs(u[c]) > 1.0 - 1e-9)
        return void(s << "the "
                      << "xyz"[c] << " axis");
    s << "(" << u.x() << ", " << u.y() << ", " << u.z() << ")";
  };
  if (rotation.norm() < 1e-6 * translation.norm()) {
    s << "a translation along ";
    direction(translation);
    return s.str();
  }
  // The axis of v(x) = t + ω × (x − centre): through centre + ω × t / |ω|².
  const Point3 through = centre + rotation.cross(translation) / rotation.squaredNorm();
  s << "a rotation about ";
  direction(rotation);
  s << " through (" << through.x() << ", " << through.y() << ", " << through.z() << ")";
  return s.str();
}

}  // namespace

std::optional<CaseError> check_rigid_motions(const CaseSpec& spec, const TetMesh& mesh) {
  // Each prescribed component c at a vertex x asks v_c(x) = 0 of a rigid motion
  // v(x) = t + ω × (x − centre), a linear condition on (t, ω); the motions that meet them all
  // are the null space of the sum of the conditions' outer products. Lengths are measured in
  // the body's diameter, so that translations and rotations compare.
  const double scale = mesh.diameter();
  Point3 centre = Point3::Zero();
  for (int v = 0; v < mesh.num_vertices(); ++v) centre += mesh.vertex(v);
  centre /= std::max(1, mesh.num_vertices());
  std::vector<int> prescribed(mesh.num_vertices(), 0);
  const auto& names = mesh.group_names();
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int g = mesh.face_group(f);
    if (g < 0) continue;
    const auto it = spec.boundary.find(names[g]);
    if (it == spec.boundary.end() || it->second.type != BoundaryCondition::Type::kDirichlet)
      continue;
    const auto& held = it->second.prescribed;
    for (int v : mesh.face(f))
      prescribed[v] |= (held[0] ? 1 : 0) | (held[1] ? 2 : 0) | (held[2] ? 4 : 0);
  }
  Matrix6 gram = Matrix6::Zero();
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Point3 r = (mesh.vertex(v) - centre) / scale;
    for (int c = 0; c < 3; ++c) {
      if (!(prescribed[v] & (1 << c))) continue;
      Vector6 row = Vector6::Zero();
      row[c] = 1.0;
      row.tail<3>() = r.cross(Point3::Unit(c));  // (ω × r)_c = ω · (r × e_c)
      gram.noalias() += row * row.transpose();
    }
  }
  // Each motion measured against what its own conditions can say (a symmetric scaling to unit
  // diagonal keeps the null space): on a slender body a rotation about its long axis moves the
  // held vertices by the thickness only, 10^-5 of the diameter for a 10^5 × 1 × 1 box, and its
  // condition must not be taken for zero next to the translations'.
  Vector6 unit = Vector6::Ones();
  for (int k = 0; k < 6; ++k)
    if (gram(k, k) > 0) unit[k] = 1.0 / std::sqrt(gram(k, k));
  const Matrix6 scaled = unit.asDiagonal() * gram * unit.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(scaled);
  std::vector<std::string> free;
  for (int k = 0; k < 6; ++k) {
    if (eigen.eigenvalues()[k] > 1e-10) continue;
    Vector6 m = unit.asDiagonal() * eigen.eigenvectors().col(k);
    m.head<3>() *= scale;
    free.push_back(describe_motion(m, centre));
  }
  if (free.empty()) return std::nullopt;
  std::ostringstream s;
  s << "the dirichlet groups leave the body free to move: their prescribed displacement "
       "components are all zero under "
    << free.size() << " independent rigid motion" << (free.size() > 1 ? "s" : "") << " (";
  for (std::size_t k = 0; k < free.size(); ++k) s << (k ? "; " : "") << free[k];
  s << "), which frictionless contact cannot stop, and the problem has no unique solution. "
       "Prescribe more components (null leaves one free), or hold another group: a rotation "
       "needs two points held across it";
  return CaseError{"/boundary", s.str()};
}

}  // namespace fosls
