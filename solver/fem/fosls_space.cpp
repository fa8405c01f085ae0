#include "fem/fosls_space.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fosls {

int prescribed_components(GroupRole role) {
  switch (role) {
    case GroupRole::kDirichlet:
      return 3;
    case GroupRole::kDirichletX:
      return 1;
    case GroupRole::kDirichletY:
      return 2;
    case GroupRole::kNeumann:
    case GroupRole::kContact:
      break;
  }
  return 0;
}

struct FoslsSpace::VertexMarks {
  std::vector<int> prescribed;  ///< bit c: u_c is Dirichlet data at the vertex
  std::vector<Point> averaged;  ///< sum of the normals of the contact edges at the vertex
  std::vector<int> curve_of;    ///< the curve of a contact edge at the vertex (−1: none)
};

FoslsSpace::FoslsSpace(const Mesh& mesh, const std::vector<GroupRole>& roles,
                       const std::vector<Point>& vertex_normals,
                       const std::vector<char>& frictional)
    : mesh_(&mesh) {
  const int nv = mesh.num_vertices(), ne = mesh.num_edges();
  if (roles.size() != mesh.group_names().size())
    throw std::logic_error("FoslsSpace: one role per boundary group expected");
  roles_.assign(num_dofs(), DofRole::kFree);
  contact_vertex_.assign(nv, 0);
  contact_edge_.assign(ne, 0);
  vertex_normal_.assign(nv, Point::Zero());
  set_vertex_roles(mark_boundary_edges(roles, frictional), vertex_normals);
  number_free_dofs();
}

FoslsSpace::VertexMarks FoslsSpace::mark_boundary_edges(const std::vector<GroupRole>& roles,
                                                        const std::vector<char>& frictional) {
  const int nv = mesh_->num_vertices(), ne = mesh_->num_edges();
  VertexMarks m;
  m.prescribed.assign(nv, 0);
  m.averaged.assign(nv, Point::Zero());
  m.curve_of.assign(nv, -1);
  for (int e = 0; e < ne; ++e) {
    int g = mesh_->edge_group(e);
    if (g < 0) continue;
    const auto& pq = mesh_->edge(e);
    switch (roles[g]) {
      case GroupRole::kDirichlet:
        m.prescribed[pq[0]] |= 3;
        m.prescribed[pq[1]] |= 3;
        break;
      case GroupRole::kDirichletX:
      case GroupRole::kDirichletY: {
        const int c = roles[g] == GroupRole::kDirichletX ? 0 : 1;
        m.prescribed[pq[0]] |= 1 << c;
        m.prescribed[pq[1]] |= 1 << c;
        roles_[sigma_dof(e, 1 - c)] = DofRole::kFixed;  // the free component's traction is 0
        break;
      }
      case GroupRole::kNeumann:
        roles_[sigma_dof(e, 0)] = roles_[sigma_dof(e, 1)] = DofRole::kFixed;
        break;
      case GroupRole::kContact:
        contact_edge_[e] = 1;
        roles_[sigma_dof(e, 0)] = DofRole::kNormalS;
        roles_[sigma_dof(e, 1)] = !frictional.empty() && frictional[g]
                                      ? DofRole::kTangentialS
                                      : DofRole::kFixed;  // σ_nt = 0
        for (int v : pq) {
          contact_vertex_[v] = 1;
          m.averaged[v] += mesh_->edge_normal(e);
          if (mesh_->edge_curve(e) >= 0) m.curve_of[v] = mesh_->edge_curve(e);
        }
        break;
    }
  }
  return m;
}

Point FoslsSpace::contact_normal(int v, const VertexMarks& marks,
                                 const std::vector<Point>& vertex_normals) const {
  const Mesh& mesh = *mesh_;
  if (!vertex_normals.empty()) return vertex_normals[v].normalized();
  if (const int curve = marks.curve_of[v]; curve >= 0) {
    // Exact normal of the arc, pointing out of the body like the edge normals do.
    Point radial = (mesh.vertex(v) - mesh.curves()[curve].center).normalized();
    return radial.dot(marks.averaged[v]) >= 0 ? radial : Point(-radial);
  }
  return marks.averaged[v].normalized();
}

void FoslsSpace::set_vertex_roles(const VertexMarks& marks,
                                  const std::vector<Point>& vertex_normals) {
  const int nv = mesh_->num_vertices();
  for (int v = 0; v < nv; ++v) {
    if (marks.prescribed[v] == 3) {
      contact_vertex_[v] = 0;  // Dirichlet data win over the contact constraint
      roles_[u_dof(v, 0)] = roles_[u_dof(v, 1)] = DofRole::kFixed;
      continue;
    }
    if (!contact_vertex_[v]) {
      for (int c = 0; c < 2; ++c)
        if (marks.prescribed[v] & (1 << c)) roles_[u_dof(v, c)] = DofRole::kFixed;
      continue;
    }
    const Point n = contact_normal(v, marks, vertex_normals);
    if (marks.prescribed[v]) {
      // Where a roller meets the contact boundary (a symmetry plane through the contact zone)
      // the prescribed axis is the tangent t = (−n_y, n_x): U_t is prescribed and U_n ≤ g
      // stays. An oblique roller cannot be both; its Dirichlet data win.
      const int c = marks.prescribed[v] == 1 ? 0 : 1;
      if (std::abs(n[c]) > 1e-12) {
        contact_vertex_[v] = 0;
        roles_[u_dof(v, c)] = DofRole::kFixed;
        continue;
      }
    }
    vertex_normal_[v] = n;
    roles_[u_dof(v, 0)] = DofRole::kNormalU;
    roles_[u_dof(v, 1)] = marks.prescribed[v] ? DofRole::kFixed : DofRole::kFree;
  }
}

void FoslsSpace::number_free_dofs() {
  full_to_free_.assign(num_dofs(), -1);
  // Reserved exactly: grown by push_back it kept up to twice its size on every level.
  free_to_full_.reserve(num_dofs() - std::count(roles_.begin(), roles_.end(), DofRole::kFixed));
  for (int d = 0; d < num_dofs(); ++d)
    if (roles_[d] != DofRole::kFixed) {
      full_to_free_[d] = static_cast<int>(free_to_full_.size());
      free_to_full_.push_back(d);
    }
}

Eigen::SparseMatrix<double> FoslsSpace::rotation() const {
  // Formed when asked for (setting up transfers, output), not kept: it is as large as a few
  // vectors of the level and nothing in a solve's iteration uses it.
  const Mesh& mesh = *mesh_;
  const int nv = mesh.num_vertices(), ne = mesh.num_edges();
  std::vector<Eigen::Triplet<double>> q;
  q.reserve(num_dofs() + 2 * nv);
  auto block = [&q](int d, const Point& n) {
    // Columns: (n, t) with t = (−n_y, n_x).
    q.emplace_back(d, d, n.x());
    q.emplace_back(d + 1, d, n.y());
    q.emplace_back(d, d + 1, -n.y());
    q.emplace_back(d + 1, d + 1, n.x());
  };
  for (int v = 0; v < nv; ++v) {
    if (contact_vertex_[v]) {
      block(u_dof(v, 0), vertex_normal_[v]);
    } else {
      q.emplace_back(u_dof(v, 0), u_dof(v, 0), 1.0);
      q.emplace_back(u_dof(v, 1), u_dof(v, 1), 1.0);
    }
  }
  for (int e = 0; e < ne; ++e) {
    if (contact_edge_[e]) {
      block(sigma_dof(e, 0), mesh.edge_normal(e));
    } else {
      q.emplace_back(sigma_dof(e, 0), sigma_dof(e, 0), 1.0);
      q.emplace_back(sigma_dof(e, 1), sigma_dof(e, 1), 1.0);
    }
  }
  Eigen::SparseMatrix<double> rotation(num_dofs(), num_dofs());
  rotation.setFromTriplets(q.begin(), q.end());
  return rotation;
}

}  // namespace fosls
