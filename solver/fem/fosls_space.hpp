#pragma once
// The discrete space X_j = P1(T_j)² × RT0(T_j)² of one level with its boundary roles:
// DOF numbering, rotated contact coordinates, fixed DOFs and bounded DOFs.

#include <Eigen/Sparse>
#include <vector>

#include "mesh/mesh.hpp"

namespace fosls {

/// Role of a boundary group in the discrete problem. kDirichletX prescribes u_x only: u_y is
/// free and its traction component t_y = (σn)_y is zero (a roller, or a symmetry plane x =
/// const); kDirichletY the other way round.
enum class GroupRole { kDirichlet, kNeumann, kContact, kDirichletX, kDirichletY };

/// The displacement components a role prescribes: bit c for component c (0 for none).
int prescribed_components(GroupRole role);

/// How a DOF enters the quadratic program.
enum class DofRole : unsigned char {
  kFree,         ///< unconstrained
  kFixed,        ///< essential: Dirichlet u, Neumann σ flux, tangential σ on contact edges
  kNormalU,      ///< U_n at a contact vertex: U_n ≤ g
  kNormalS,      ///< S_n on a contact edge: S_n ≤ 0
  kTangentialS,  ///< S_t on a frictional contact edge: |S_t| ≤ s̄ (docs/method.md §8)
};

/// Full DOF vector layout: u_c at vertex v is 2v + c; σ row i on edge e is 2·nv + 2e + i.
/// At contact vertices the pair (2v, 2v+1) holds (U_n, U_t) with U_n = n_v·U_v, U_t = t_v·U_v,
/// t = (−n_y, n_x); on contact edges the pair holds (S_n, S_t) = (Σ n_i S_i, Σ t_i S_i).
class FoslsSpace {
 public:
  /// `roles[g]` is the role of mesh group g. `vertex_normals` gives the constraint direction
  /// at each contact vertex (ignored elsewhere; empty = the normalised average of the adjacent
  /// contact edge normals). `frictional[g]` (empty: none) makes S_t of group g's contact edges
  /// free and bounded instead of fixed at σ_nt = 0.
  FoslsSpace(const Mesh& mesh, const std::vector<GroupRole>& roles,
             const std::vector<Point>& vertex_normals = {},
             const std::vector<char>& frictional = {});

  const Mesh& mesh() const { return *mesh_; }
  int num_dofs() const { return 2 * mesh_->num_vertices() + 2 * mesh_->num_edges(); }
  int u_dof(int v, int c) const { return 2 * v + c; }
  int sigma_dof(int e, int i) const { return 2 * mesh_->num_vertices() + 2 * e + i; }

  DofRole role(int dof) const { return roles_[dof]; }
  bool is_contact_vertex(int v) const { return contact_vertex_[v] != 0; }
  bool is_contact_edge(int e) const { return contact_edge_[e] != 0; }
  /// Constraint direction n_v at a contact vertex.
  const Point& vertex_normal(int v) const { return vertex_normal_[v]; }

  /// Rotation Q with x_cartesian = Q x_rotated (orthogonal, 2×2 blocks at contact DOFs),
  /// formed on each call.
  Eigen::SparseMatrix<double> rotation() const;

  int num_free() const { return static_cast<int>(free_to_full_.size()); }
  const std::vector<int>& free_to_full() const { return free_to_full_; }
  /// Free index of a full DOF, -1 for fixed DOFs.
  int free_index(int dof) const { return full_to_free_[dof]; }

 private:
  /// What the boundary groups say about each vertex (the constructor's first step).
  struct VertexMarks;
  /// Roles of the edges' DOFs from their group's role; contact edges and vertices marked.
  VertexMarks mark_boundary_edges(const std::vector<GroupRole>& roles,
                                  const std::vector<char>& frictional);
  /// Roles of the vertices' DOFs and the contact normals, from the marks.
  void set_vertex_roles(const VertexMarks& marks, const std::vector<Point>& vertex_normals);
  /// The normal of contact vertex v: given, the arc's exact one, or the edges' average.
  Point contact_normal(int v, const VertexMarks& marks,
                       const std::vector<Point>& vertex_normals) const;
  /// The free DOFs (all but the fixed ones), numbered in DOF order.
  void number_free_dofs();

  const Mesh* mesh_;
  std::vector<DofRole> roles_;
  std::vector<char> contact_vertex_, contact_edge_;
  std::vector<Point> vertex_normal_;
  std::vector<int> free_to_full_, full_to_free_;
};

}  // namespace fosls
