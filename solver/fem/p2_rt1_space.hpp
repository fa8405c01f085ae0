#pragma once
// The order-2 space P2(T)² × RT1(T)² on one mesh with its boundary roles (docs/method.md §10):
// DOF numbering, rotated contact coordinates, fixed and bounded DOFs — FoslsSpace's roles for
// twice the nodes.

#include <Eigen/Sparse>
#include <vector>

#include "fem/fosls_space.hpp"

namespace fosls {

/// DOF layout. Displacement nodes: vertex v is node v, the midpoint of edge e node nv + e; u_c
/// at node a is 2a + c. Stress edge nodes: end j of edge e (its global orientation) is node
/// 2e + j; row i there is 2(nv + ne) + 2(2e + j) + i. Triangle t's mean of row i, component m,
/// is 2(nv + ne) + 4ne + 4t + 2m + i. At contact nodes the pairs hold rotated coordinates as in
/// FoslsSpace: (U_n, U_t) and (S_n, S_t), S_t fixed at 0 (frictionless).
class P2Rt1Space {
 public:
  /// `groups[g]` says what mesh group g does (as FoslsSpace's); a frictional contact group is
  /// not supported.
  P2Rt1Space(const Mesh& mesh, const std::vector<BoundaryRole>& groups);

  const Mesh& mesh() const { return *mesh_; }
  int num_u_nodes() const { return mesh_->num_vertices() + mesh_->num_edges(); }
  int num_dofs() const { return 2 * num_u_nodes() + 4 * mesh_->num_edges() + 4 * triangles(); }
  int u_dof(int node, int c) const { return 2 * node + c; }
  int midpoint_node(int e) const { return mesh_->num_vertices() + e; }
  int sigma_edge_dof(int e, int j, int i) const { return 2 * num_u_nodes() + 2 * (2 * e + j) + i; }
  int sigma_mean_dof(int t, int m, int i) const {
    return 2 * num_u_nodes() + 4 * mesh_->num_edges() + 4 * t + 2 * m + i;
  }
  /// The 28 DOFs of triangle t in the element's order: u of its six P2 nodes (2n + c), then
  /// σ of its eight RT1 functions (12 + 2m + i).
  static constexpr int kCellDofs = 28;
  std::array<int, kCellDofs> cell_dofs(int t) const;

  DofRole role(int dof) const { return roles_[dof]; }
  bool is_contact_node(int node) const { return contact_node_[node] != 0; }
  bool is_contact_edge(int e) const { return contact_edge_[e] != 0; }
  /// Constraint direction at a contact node.
  const Point& node_normal(int node) const { return node_normal_[node]; }
  /// Where a displacement node lies: a vertex, an edge's midpoint, or for a boundary edge on
  /// an arc the point of the arc nearest to the midpoint.
  Point node_position(int node) const;

  /// Rotation Q with x_cartesian = Q x_rotated.
  Eigen::SparseMatrix<double> rotation() const;

  int num_free() const { return static_cast<int>(free_to_full_.size()); }
  const std::vector<int>& free_to_full() const { return free_to_full_; }
  int free_index(int dof) const { return full_to_free_[dof]; }

 private:
  int triangles() const { return mesh_->num_triangles(); }
  /// Roles of the stress DOFs of boundary edges; returns the prescribed bits of each node and
  /// marks the contact edges and nodes with the sums of their edge normals.
  std::vector<int> mark_boundary_edges(const std::vector<BoundaryRole>& groups,
                                       std::vector<Point>& averaged);
  void set_node_roles(const std::vector<int>& prescribed, const std::vector<Point>& averaged);
  void number_free_dofs();

  const Mesh* mesh_;
  std::vector<DofRole> roles_;
  std::vector<char> contact_node_, contact_edge_;
  std::vector<Point> node_normal_;
  std::vector<int> free_to_full_, full_to_free_;
};

}  // namespace fosls
