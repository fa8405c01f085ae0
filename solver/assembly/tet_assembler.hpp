#pragma once
// Assembly of the FOSLS functional in three dimensions (docs/method.md §11, stage 1: linear
// elasticity) into the BoxQp every solver works on (here without bounds).

#include <functional>
#include <vector>

#include "assembly/fosls_assembler.hpp"
#include "core/box_qp.hpp"
#include "fem/fosls_space.hpp"

namespace fosls {

using ScalarFunction3 = std::function<double(const Point3&)>;

/// A 3D problem: material, weights, body force and per mesh group its role and data (u_D or
/// t_N, Cartesian components, empty is zero; for contact the gap g ≥ u·n along the body normal).
struct TetProblemData {
  ElasticMaterial material;
  FunctionalWeights weights;
  std::array<ScalarFunction3, 3> body_force;
  struct Group {
    GroupRole role = GroupRole::kNeumann;
    std::array<ScalarFunction3, 3> values;
    /// Dirichlet: the prescribed components (bit c for u_c); the others are free with zero
    /// traction (a roller or symmetry plane).
    int prescribed = 7;
    /// Neumann: values[0] is a pressure p, the traction −p n with the face's outward normal.
    bool normal_pressure = false;
    ScalarFunction3 gap;  ///< contact
    /// Contact: the gap at x along the body's unit outward normal n there (a rigid plane's
    /// distance along n); used instead of `gap` when set, with the vertex's averaged normal.
    std::function<double(const Point3& x, const Point3& n)> gap_along_normal;
  };
  std::vector<Group> groups;  ///< indexed like TetMesh::group_names()
  std::vector<BoundaryRole> boundary_roles() const {
    std::vector<BoundaryRole> r;
    for (const Group& g : groups) r.push_back({g.role, g.prescribed});
    return r;
  }
};

struct TetAssembledProblem {
  BoxQp qp;             ///< over the free DOFs, stresses in units of μ
  Vector fixed_values;  ///< full vector: the fixed DOFs' values, zero elsewhere
  double stress_scale = 1.0;
};

class TetAssembler {
 public:
  TetAssembler(const FoslsSpace<3>& space, const TetProblemData& data);

  const FoslsSpace<3>& space() const { return space_; }
  const TetProblemData& data() const { return data_; }
  TetAssembledProblem assemble_system() const;
  Vector full_vector(const TetAssembledProblem& p, const Vector& x_free) const;
  /// J at a full DOF vector (`element` per tetrahedron, the contact term of a contact face
  /// added to its tetrahedron's).
  FunctionalParts functional(const Vector& x_full) const;
  /// ∫_Γ_C σn dA in physical units: the obstacle's force on the body.
  Point3 contact_force(const Vector& x_full) const;
  /// The contact pressure −σ_nn of each face in physical units (RT0: constant on a face; zero
  /// off the contact boundary).
  std::vector<double> contact_pressure(const Vector& x_full) const;

 private:
  struct Local;
  void element_kernel(int t, Local& out) const;
  /// The local matrix and vector in the rotated coordinates of contact vertices and faces.
  void rotate_local(int t, Local& loc) const;
  Vector essential_values() const;
  /// The fixed u of roller groups (Dirichlet groups prescribing some components) in xd, at
  /// vertices not `held` by a full Dirichlet group: the Cartesian component, or on the contact
  /// boundary the tangential U_t along that axis.
  void set_roller_values(const std::vector<char>& held, Vector& xd) const;
  /// C3 ⟨u·n − g, σ_nn⟩ on face f as (DOF, coefficient of S_n) pairs — u·n linear between the
  /// vertices (U_n at a contact vertex, n_f·u at a Dirichlet one), σ_nn = S_n/|f| — and the
  /// gap's part.
  std::vector<std::pair<int, double>> contact_couplings(int f) const;
  double contact_gap_term(int f) const;

  const FoslsSpace<3>& space_;
  const TetProblemData& data_;
  double mu_ = 1.0;
  double kappa_ = 1.0 / 3.0;        ///< λ / (3λ + 2μ), → ⅓ as λ → ∞
  std::vector<double> vertex_gap_;  ///< g at the vertices of contact faces, +inf elsewhere
};

}  // namespace fosls
