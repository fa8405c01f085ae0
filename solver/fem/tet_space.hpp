#pragma once
// The 3D space X_j = P1(T_j)³ × RT0(T_j)³ of one level with its boundary roles (docs/method.md
// §11): Dirichlet, Neumann and frictionless contact groups.

#include <Eigen/Sparse>
#include <vector>

#include "fem/fosls_space.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

/// The frame (n, t1, t2) of a unit normal n: t1 ⟂ n along the coordinate axis least aligned
/// with n, t2 = n × t1; as the columns of an orthogonal matrix.
Eigen::Matrix3d normal_frame(const Point3& n);

/// A roller's axis may meet the contact boundary where the body's normal is within 30° of the
/// roller's plane (a symmetry plane through the contact zone meets it at 0°).
constexpr double kRollerCosine = 0.8660254037844386;  // cos 30°

/// The frame of a contact vertex with averaged unit normal `normal` where Dirichlet groups
/// prescribe the components `prescribed` (bit c for u_c): the normal with those components
/// removed, renormalised, so that the first prescribed axis is t1 and a second one ±t2; zero
/// when the normal is further than 30° from the rollers' planes. normal_frame without rollers.
Eigen::Matrix3d roller_frame(const Point3& normal, int prescribed);

/// DOF layout: u_c at vertex v is 3v + c; σ row i on face f is 3·n_v + 3f + i (the flux
/// ∫_f σ_i·n_f through the face with its global normal). At a contact vertex the triple holds
/// (U_n, U_t1, U_t2) in the vertex's normal frame, on a contact face (S_n, S_t1, S_t2) in the
/// face's (σ_nt = 0: S_t fixed).
class TetSpace {
 public:
  /// `roles[g]` for mesh group g: kDirichlet (u fixed), kNeumann (σ·n fixed) or kContact
  /// (U_n ≤ g, S_n ≤ 0 along the normal of the faces, averaged at vertices); ungrouped boundary
  /// faces are traction free. `prescribed[g]` (empty: all) the components a Dirichlet group
  /// fixes, bit c for u_c; the others are free with zero traction (σ rows fixed). Throws
  /// std::invalid_argument for the 2D roller roles.
  TetSpace(const TetMesh& mesh, const std::vector<GroupRole>& roles,
           const std::vector<int>& prescribed = {});

  const TetMesh& mesh() const { return *mesh_; }
  int num_dofs() const { return 3 * mesh_->num_vertices() + 3 * mesh_->num_faces(); }
  int u_dof(int v, int c) const { return 3 * v + c; }
  int sigma_dof(int f, int i) const { return 3 * mesh_->num_vertices() + 3 * f + i; }
  DofRole role(int dof) const { return roles_[dof]; }
  bool fixed(int dof) const { return roles_[dof] == DofRole::kFixed; }
  bool is_contact_vertex(int v) const { return !vertex_frame_[v].isZero(); }
  bool is_contact_face(int f) const { return contact_face_[f] != 0; }
  /// The frame (n, t1, t2) of a contact vertex (zero elsewhere).
  const Eigen::Matrix3d& vertex_frame(int v) const { return vertex_frame_[v]; }
  /// The 24 DOFs of tetrahedron t: u of its vertices (3k + c), then σ of its faces
  /// (12 + 3k + i).
  std::array<int, 24> tet_dofs(int t) const;
  /// Rotation Q with x_cartesian = Q x_rotated (3×3 blocks at contact vertices and faces).
  Eigen::SparseMatrix<double> rotation() const;

  int num_free() const { return static_cast<int>(free_to_full_.size()); }
  const std::vector<int>& free_to_full() const { return free_to_full_; }
  int free_index(int dof) const { return full_to_free_[dof]; }

 private:
  /// Fixed u DOFs and contact frames from the components prescribed at each vertex and the
  /// sum of its contact faces' normals.
  void set_vertex_roles(const std::vector<int>& prescribed, const std::vector<Point3>& normal_sum);

  const TetMesh* mesh_;
  std::vector<DofRole> roles_;
  std::vector<char> contact_face_;
  std::vector<Eigen::Matrix3d> vertex_frame_;
  std::vector<int> free_to_full_, full_to_free_;
};

}  // namespace fosls
