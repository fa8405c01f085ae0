#pragma once
// The rotated coordinates of the contact DOFs (docs/method.md §3 and §11): the frame of a
// normal, and the frame of a contact vertex where rollers (prescribed displacement components,
// symmetry planes) meet the contact boundary — one roller mechanism for both dimensions.

#include "mesh/simplex_mesh.hpp"

namespace fosls {

/// The frame of a unit normal n as the columns of an orthogonal matrix: (n, t) with
/// t = (−n_y, n_x) in 2D; (n, t1, t2) in 3D with t1 ⟂ n along the coordinate axis least aligned
/// with n and t2 = n × t1.
template <int dim>
Mat<dim> normal_frame(const Vec<dim>& n);

/// A roller's axis may meet the contact boundary where the body's normal is within 30° of the
/// roller's plane (a symmetry plane through the contact zone meets it at 0°).
constexpr double kRollerCosine = 0.8660254037844386;  // cos 30°

/// The frame of a contact vertex with unit normal `normal` where Dirichlet groups prescribe the
/// displacement components `prescribed` (bit c for u_c, not all of them): the normal with those
/// components removed and renormalised, so that the prescribed axes are tangents — in 3D the
/// first prescribed axis is t1 and a second one ±t2, in 2D the axis is ±t — and U_n ≤ g stays;
/// zero when the normal is further than 30° from the rollers' planes (their data win there).
/// normal_frame without rollers.
template <int dim>
Mat<dim> roller_frame(const Vec<dim>& normal, int prescribed);

}  // namespace fosls
