#pragma once
// The built-in half ball of the 3D Hertz problem (docs/validation.md §16): flat face up, the
// curved face down onto a plane, graded towards the south pole where contact happens.

#include "mesh/tet_mesh.hpp"

namespace fosls {

struct HalfBallSpec {
  double radius = 1.0;
  int cells = 4;                  ///< Kuhn cubes along the depth; 2 × cells across
  double grading = 2.0;           ///< element sizes ∝ (distance to the pole)^(grading − 1)
  double contact_fraction = 0.5;  ///< of the radius: the contact group's extent about the axis
  /// Only the quarter x ≥ 0, y ≥ 0, with the groups symmetry_x (x = 0) and symmetry_y (y = 0):
  /// exactly the whole mesh's tetrahedra there, which is mirror symmetric, so with rollers on
  /// the two planes it gives a quarter of the whole ball's solution.
  bool quarter = false;
};

/// The half ball {|x| ≤ R, z ≤ 0}: a Kuhn mesh of the half cube [−1, 1]² × [−1, 0] whose cubes'
/// diagonals point away from the origin (so no tetrahedron has four vertices on the sphere), graded
/// towards its pole p = (0, 0, −1) by ξ ↦ p + (ξ − p) |ξ − p|^(grading − 1) where |ξ − p| < 1,
/// then mapped onto the half ball radially (x ↦ R x ‖x‖_∞ / ‖x‖₂, which keeps z = 0 flat and takes
/// the other five faces onto the sphere). Groups: `top` (z = 0), `contact` (sphere faces whose
/// centroid lies within contact_fraction · R of the axis) and `free` (the rest of the sphere); both
/// sphere groups carry the sphere, so refinement stays on it. Throws std::invalid_argument for a
/// spec that is out of range or would fold a tetrahedron.
TetMesh make_half_ball(const HalfBallSpec& spec);

}  // namespace fosls
