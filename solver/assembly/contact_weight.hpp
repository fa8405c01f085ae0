#pragma once
// The weight c3 of the contact term, chosen from the mesh instead of guessed.
//
// J = J0 + c3·⟨u·n − g, σ_nn⟩ where J0 (the c1, c2, c4 terms) is a sum of squares and the
// contact term is bilinear and indefinite. With A0 the matrix of J0 and B that of the contact
// term, A0 + c3·B is positive definite exactly for c3 < c3* = −1/μ_min, μ_min the smallest
// eigenvalue of the pencil B x = μ A0 x (docs/method.md §2.1). c3* depends on the geometry, by
// more than an order of magnitude between a block and a long thin strip, so no fixed default
// fits every case. The rule: c3 = min(0.1, c3* / 2), with c3* computed on the finest level of
// at most kWeightLevelDofs unknowns (c3* converges under refinement — the trace inequality
// bounds the contact term by the H¹ × H(div) norm — and the factor ½ covers the difference to
// the finest level: docs/performance.md, "Measurements behind choices in the code").

#include "assembly/problem_data.hpp"
#include "mesh/refinement.hpp"
#include "mesh/simplex_mesh.hpp"

namespace fosls {

/// The definiteness limit of c3 on one level and where it was computed.
struct ContactWeightLimit {
  double limit = 0.0;  ///< c3*, +infinity when the contact term is positive semidefinite
  int level = 0;       ///< mesh level it was computed on
  int dofs = 0;        ///< free unknowns of that level
  int lanczos_steps = 0;
};

/// Largest level with at most this many free unknowns that the limit is computed on.
constexpr int kWeightLevelDofs = 20000;

/// c3* on the finest level of `meshes` with at most `max_dofs` free unknowns (the coarsest if
/// none is that small), in 2D or 3D. `data.weights.c3` is ignored.
template <int dim>
ContactWeightLimit contact_weight_limit(const SimplexHierarchy<dim>& meshes,
                                        const ProblemData<dim>& data,
                                        int max_dofs = kWeightLevelDofs);

/// The rule applied to a limit: min(kDefaultContactWeight, limit / 2).
double automatic_contact_weight(const ContactWeightLimit& limit);
constexpr double kDefaultContactWeight = 0.1;

}  // namespace fosls
