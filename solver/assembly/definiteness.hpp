#pragma once
// Whether the FOSLS matrix is positive definite, checked where it can fail.
//
// Without a contact group J is a sum of squares. The contact term C3 ⟨u·n − g, σ_nn⟩ is
// bilinear and indefinite by itself, so too large a C3 makes A indefinite through modes that
// live at the contact boundary (method.md §2). The check factorises the principal submatrix of
// A on the DOFs of the triangles within two layers of the contact boundary: cheap (O(boundary))
// and, since every principal submatrix of an SPD matrix is SPD, never a false alarm.

#include "assembly/fosls_assembler.hpp"
#include "core/level_hierarchy.hpp"

namespace fosls {

/// True when the boundary-layer submatrix has a positive definite LDLᵀ factorisation.
/// Catches weights far from the limit; near it the indefinite modes are wider than the layer.
bool contact_layer_is_definite(const FoslsSpace& space, const BoxQp& qp);

/// True when the Galerkin matrix PᵀAP of the finest level with at most `max_dofs` DOFs (A
/// itself when it is small enough) has a CHOLMOD Cholesky factorisation. PᵀAP indefinite
/// implies A indefinite, and the measured limit on c3 barely moves with h (0.28, 0.26, 0.25
/// at 3, 4, 5 levels of the square), so a level of ≈10⁵ DOFs decides reliably at a fraction
/// of the cost of factorising the finest matrix.
bool galerkin_is_definite(const SparseMatrix& A, const LevelHierarchy& hierarchy,
                          int max_dofs = 150000);

}  // namespace fosls
