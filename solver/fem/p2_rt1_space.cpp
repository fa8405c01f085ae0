#include "fem/p2_rt1_space.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/contact_frame.hpp"

namespace fosls {

P2Rt1Space::P2Rt1Space(const Mesh& mesh, const std::vector<BoundaryRole>& groups) : mesh_(&mesh) {
  if (groups.size() != mesh.group_names().size())
    throw std::logic_error("P2Rt1Space: one role per boundary group expected");
  roles_.assign(num_dofs(), DofRole::kFree);
  contact_node_.assign(num_u_nodes(), 0);
  contact_edge_.assign(mesh.num_edges(), 0);
  node_normal_.assign(num_u_nodes(), Point::Zero());
  std::vector<Point> averaged(num_u_nodes(), Point::Zero());
  const std::vector<int> prescribed = mark_boundary_edges(groups, averaged);
  set_node_roles(prescribed, averaged);
  number_free_dofs();
}

std::vector<int> P2Rt1Space::mark_boundary_edges(const std::vector<BoundaryRole>& groups,
                                                 std::vector<Point>& averaged) {
  std::vector<int> prescribed(num_u_nodes(), 0);
  for (int e = 0; e < mesh_->num_edges(); ++e) {
    const int g = mesh_->edge_group(e);
    if (g < 0) continue;
    const auto& pq = mesh_->edge(e);
    const std::array<int, 3> nodes = {pq[0], pq[1], midpoint_node(e)};
    auto fix_sigma_row = [&](int i) {
      for (int j = 0; j < 2; ++j) roles_[sigma_edge_dof(e, j, i)] = DofRole::kFixed;
    };
    if (groups[g].role == GroupRole::kDirichlet) {
      const int bits = groups[g].prescribed & 3;
      for (int a : nodes) prescribed[a] |= bits;
      for (int i = 0; i < 2; ++i)  // a free component's traction is 0
        if (!(bits & (1 << i))) fix_sigma_row(i);
    } else if (groups[g].role == GroupRole::kNeumann) {
      fix_sigma_row(0);
      fix_sigma_row(1);
    } else {
      contact_edge_[e] = 1;
      for (int j = 0; j < 2; ++j) roles_[sigma_edge_dof(e, j, 0)] = DofRole::kNormalS;
      fix_sigma_row(1);  // σ_nt = 0 in the rotated pair
      for (int a : nodes) {
        contact_node_[a] = 1;
        averaged[a] += mesh_->edge_normal(e);
      }
      if (const int curve = mesh_->edge_curve(e); curve >= 0)
        for (int a : nodes) {
          // The exact normal of the arc, outwards like the edge normals.
          const Point radial = (node_position(a) - mesh_->curves()[curve].center).normalized();
          node_normal_[a] = radial.dot(mesh_->edge_normal(e)) >= 0 ? radial : Point(-radial);
        }
    }
  }
  return prescribed;
}

void P2Rt1Space::set_node_roles(const std::vector<int>& prescribed,
                                const std::vector<Point>& averaged) {
  for (int a = 0; a < num_u_nodes(); ++a) {
    if (contact_node_[a] && prescribed[a] != 3) {
      // FoslsSpace's rule: a roller meets the contact boundary where its axis is a tangent
      // (contact_frame.hpp).
      const Point n =
          node_normal_[a].squaredNorm() > 0 ? node_normal_[a] : averaged[a].normalized();
      const Mat<2> frame = roller_frame<2>(n, prescribed[a]);
      if (!frame.isZero()) {
        node_normal_[a] = frame.col(0);
        roles_[u_dof(a, 0)] = DofRole::kNormalU;
        if (prescribed[a]) roles_[u_dof(a, 1)] = DofRole::kFixed;
        continue;
      }
    }
    contact_node_[a] = 0;
    node_normal_[a] = Point::Zero();
    for (int k = 0; k < 2; ++k)
      if (prescribed[a] & (1 << k)) roles_[u_dof(a, k)] = DofRole::kFixed;
  }
}

void P2Rt1Space::number_free_dofs() {
  full_to_free_.assign(num_dofs(), -1);
  free_to_full_.clear();
  for (int d = 0; d < num_dofs(); ++d)
    if (roles_[d] != DofRole::kFixed) {
      full_to_free_[d] = static_cast<int>(free_to_full_.size());
      free_to_full_.push_back(d);
    }
}

Point P2Rt1Space::node_position(int node) const {
  const int nv = mesh_->num_vertices();
  if (node < nv) return mesh_->vertex(node);
  const int e = node - nv, curve = mesh_->edge_curve(e);
  // On an arc the node stands for the boundary point it approximates (the vertices lie on it).
  return curve < 0 ? mesh_->edge_midpoint(e)
                   : mesh_->curves()[curve].project(mesh_->edge_midpoint(e));
}

std::array<int, P2Rt1Space::kCellDofs> P2Rt1Space::cell_dofs(int t) const {
  std::array<int, 28> d;
  const auto& tri = mesh_->triangle(t);
  for (int k = 0; k < 3; ++k) {
    const int e = mesh_->triangle_edge(t, k);
    for (int c = 0; c < 2; ++c) {
      d[2 * k + c] = u_dof(tri[k], c);
      d[2 * (3 + k) + c] = u_dof(midpoint_node(e), c);
      for (int j = 0; j < 2; ++j) d[12 + 2 * (2 * k + j) + c] = sigma_edge_dof(e, j, c);
    }
  }
  for (int m = 0; m < 2; ++m)
    for (int i = 0; i < 2; ++i) d[12 + 2 * (6 + m) + i] = sigma_mean_dof(t, m, i);
  return d;
}

Eigen::SparseMatrix<double> P2Rt1Space::rotation() const {
  std::vector<Eigen::Triplet<double>> q;
  q.reserve(num_dofs() + 2 * num_u_nodes());
  std::vector<char> rotated(num_dofs(), 0);
  auto block = [&](int d, const Point& n) {  // columns (n, t), t = (−n_y, n_x)
    q.emplace_back(d, d, n.x());
    q.emplace_back(d + 1, d, n.y());
    q.emplace_back(d, d + 1, -n.y());
    q.emplace_back(d + 1, d + 1, n.x());
    rotated[d] = rotated[d + 1] = 1;
  };
  for (int a = 0; a < num_u_nodes(); ++a)
    if (contact_node_[a]) block(u_dof(a, 0), node_normal_[a]);
  for (int e = 0; e < mesh_->num_edges(); ++e)
    if (contact_edge_[e])
      for (int j = 0; j < 2; ++j) block(sigma_edge_dof(e, j, 0), mesh_->edge_normal(e));
  for (int d = 0; d < num_dofs(); ++d)
    if (!rotated[d]) q.emplace_back(d, d, 1.0);
  Eigen::SparseMatrix<double> rotation(num_dofs(), num_dofs());
  rotation.setFromTriplets(q.begin(), q.end());
  return rotation;
}

}  // namespace fosls
