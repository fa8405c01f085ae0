#include "fem/tet_space.hpp"

#include <Eigen/Geometry>
#include <bit>
#include <stdexcept>

namespace fosls {

Eigen::Matrix3d normal_frame(const Point3& n) {
  int axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  const Point3 t1 = n.cross(Point3::Unit(axis)).normalized();
  Eigen::Matrix3d q;
  q.col(0) = n;
  q.col(1) = t1;
  q.col(2) = n.cross(t1);
  return q;
}

Eigen::Matrix3d roller_frame(const Point3& normal, int prescribed) {
  Point3 n = normal;
  int first = -1;
  for (int c = 0; c < 3; ++c)
    if (prescribed & (1 << c)) {
      n[c] = 0.0;
      if (first < 0) first = c;
    }
  if (first < 0) return normal_frame(normal);
  if (n.norm() < kRollerCosine * normal.norm()) return Eigen::Matrix3d::Zero();
  n.normalize();
  Eigen::Matrix3d q;
  q.col(0) = n;
  q.col(1) = Point3::Unit(first);
  q.col(2) = n.cross(q.col(1));
  return q;
}

TetSpace::TetSpace(const TetMesh& mesh, const std::vector<GroupRole>& roles,
                   const std::vector<int>& prescribed)
    : mesh_(&mesh) {
  if (roles.size() != mesh.group_names().size() ||
      (!prescribed.empty() && prescribed.size() != roles.size()))
    throw std::logic_error("TetSpace: one role per boundary group expected");
  roles_.assign(num_dofs(), DofRole::kFree);
  contact_face_.assign(mesh.num_faces(), 0);
  std::vector<int> vertex_prescribed(mesh.num_vertices(), 0);
  std::vector<Point3> normal_sum(mesh.num_vertices(), Point3::Zero());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int g = mesh.face_group(f);
    if (g < 0) continue;
    switch (roles[g]) {
      case GroupRole::kDirichlet: {
        const int bits = prescribed.empty() ? 7 : prescribed[g];
        for (int v : mesh.face(f)) vertex_prescribed[v] |= bits;
        for (int i = 0; i < 3; ++i)  // a free component's traction is zero (a roller)
          if (!(bits & (1 << i))) roles_[sigma_dof(f, i)] = DofRole::kFixed;
        break;
      }
      case GroupRole::kNeumann:
        for (int i = 0; i < 3; ++i) roles_[sigma_dof(f, i)] = DofRole::kFixed;
        break;
      case GroupRole::kContact:
        contact_face_[f] = 1;
        roles_[sigma_dof(f, 0)] = DofRole::kNormalS;
        roles_[sigma_dof(f, 1)] = roles_[sigma_dof(f, 2)] = DofRole::kFixed;  // σ_nt = 0
        for (int v : mesh.face(f)) normal_sum[v] += mesh.face_normal(f);
        break;
      default:
        throw std::invalid_argument("3D: Dirichlet, Neumann and contact groups only");
    }
  }
  set_vertex_roles(vertex_prescribed, normal_sum);
  full_to_free_.assign(num_dofs(), -1);
  for (int d = 0; d < num_dofs(); ++d)
    if (roles_[d] != DofRole::kFixed) {
      full_to_free_[d] = static_cast<int>(free_to_full_.size());
      free_to_full_.push_back(d);
    }
}

void TetSpace::set_vertex_roles(const std::vector<int>& prescribed,
                                const std::vector<Point3>& normal_sum) {
  vertex_frame_.assign(mesh_->num_vertices(), Eigen::Matrix3d::Zero());
  for (int v = 0; v < mesh_->num_vertices(); ++v) {
    const int bits = prescribed[v];
    if (bits == 7) {  // Dirichlet data win over the contact constraint
      for (int c = 0; c < 3; ++c) roles_[u_dof(v, c)] = DofRole::kFixed;
      continue;
    }
    if (normal_sum[v].squaredNorm() > 0) {
      // Where rollers meet the contact boundary (symmetry planes through the contact zone) the
      // prescribed axes become the frame's tangents, fixed, and U_n ≤ g stays.
      vertex_frame_[v] = roller_frame(normal_sum[v].normalized(), bits);
      if (!vertex_frame_[v].isZero()) {
        roles_[u_dof(v, 0)] = DofRole::kNormalU;
        for (int k = 1; k <= std::popcount(static_cast<unsigned>(bits)); ++k)
          roles_[u_dof(v, k)] = DofRole::kFixed;
        continue;
      }
    }
    for (int c = 0; c < 3; ++c)  // an oblique roller cannot be both: its data win
      if (bits & (1 << c)) roles_[u_dof(v, c)] = DofRole::kFixed;
  }
}

std::array<int, 24> TetSpace::tet_dofs(int t) const {
  std::array<int, 24> d;
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) {
      d[3 * k + c] = u_dof(mesh_->tet(t)[k], c);
      d[12 + 3 * k + c] = sigma_dof(mesh_->tet_face(t, k), c);
    }
  return d;
}

Eigen::SparseMatrix<double> TetSpace::rotation() const {
  std::vector<Eigen::Triplet<double>> q;
  auto block = [&q](int d, const Eigen::Matrix3d& frame) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) q.emplace_back(d + r, d + c, frame(r, c));
  };
  auto identity = [&q](int d) {
    for (int r = 0; r < 3; ++r) q.emplace_back(d + r, d + r, 1.0);
  };
  for (int v = 0; v < mesh_->num_vertices(); ++v)
    is_contact_vertex(v) ? block(u_dof(v, 0), vertex_frame_[v]) : identity(u_dof(v, 0));
  for (int f = 0; f < mesh_->num_faces(); ++f)
    is_contact_face(f) ? block(sigma_dof(f, 0), normal_frame(mesh_->face_normal(f)))
                       : identity(sigma_dof(f, 0));
  Eigen::SparseMatrix<double> rotation(num_dofs(), num_dofs());
  rotation.setFromTriplets(q.begin(), q.end());
  return rotation;
}

}  // namespace fosls
