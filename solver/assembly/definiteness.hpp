#pragma once
// Whether the FOSLS matrix is positive definite, checked where it can fail.
//
// Without a contact group J is a sum of squares. The contact term C3 ⟨u·n − g, σ_nn⟩ is
// bilinear and indefinite by itself, so too large a C3 makes A indefinite through modes that
// live at the contact boundary (docs/method.md §2). The check factorises the principal submatrix of
// A on the DOFs of the triangles within two layers of the contact boundary: cheap (O(boundary))
// and, since every principal submatrix of an SPD matrix is SPD, never a false alarm.

#include "assembly/fosls_assembler.hpp"

namespace fosls {

/// True when the boundary-layer submatrix has a positive definite LDLᵀ factorisation.
/// Catches weights far from the limit, cheaply and before anything else is built; near the
/// limit the indefinite modes are wider than the layer and the solvers' own checks decide
/// (chain_is_definite for mmg and tnnmg, CHOLMOD for pdas).
bool contact_layer_is_definite(const FoslsSpace<2>& space, const BoxQp& qp);

}  // namespace fosls
