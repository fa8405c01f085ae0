#pragma once
// Friction on contact edges (docs/method.md §8). On a frictional edge e the functional has the
// term C3 ∫_e (σ_nt Δu_t + s |Δu_t|)/μ, Δu_t the slip from the reference state: its bilinear
// part C3 S_t (ΔU_t,p + ΔU_t,q)/2 is assembled with the normal term (fosls_assembler.cpp), its
// kinks C3 s̄_e/2 |ΔU_t,v| at the end points (trapezoidal rule) and the bounds |S_t| ≤ s̄_e,
// s̄_e = ∫_e s/μ, are set here. Coulomb's s = 𝔣 |σ_nn| makes s̄_e = 𝔣 max(0, −S_n).

#include "assembly/problem_data.hpp"
#include "core/friction_law.hpp"
#include "core/kinks.hpp"

namespace fosls {

/// The tangential displacement t·u_ref(v) of the reference state at vertex v (0 without one).
double reference_slip_origin(const ProblemData<2>& data, int v, const Point& tangent);

/// The slip direction t = (−n_y, n_x) at vertex v of contact edge e: n is the vertex's contact
/// normal where its displacement is rotated into (n, t), else the edge's normal.
Point slip_tangent(const FoslsSpace<2>& space, int e, int v);

/// u·t at vertex v from a full DOF vector: the rotated U_t of a contact vertex, else t·u.
double tangential_displacement(const FoslsSpace<2>& space, const Vector& x_full, int v,
                               const Point& t);

/// The frictional edges of `space`, their kinks in `kinks` (DOFs and origins; weights zero) and
/// Tresca's s̄_e. `xd` holds the fixed DOFs' values. A negative Tresca bound throws
/// std::domain_error naming the point.
FrictionLayout friction_layout(const FoslsSpace<2>& space, const ProblemData<2>& data,
                               const Vector& xd, Kinks& kinks);

}  // namespace fosls
