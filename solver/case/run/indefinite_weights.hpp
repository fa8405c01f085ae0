#pragma once
// What a user is told when the FOSLS matrix of a case is not positive definite, in 2D and 3D:
// a body too thin for double precision, or weights whose contact term c3 is too large (with the
// limit on this mesh, or how "auto" chose c3), or rollers that leave a rigid motion free.

#include <string>

#include "assembly/problem_data.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_spec.hpp"
#include "mesh/simplex_mesh.hpp"

namespace fosls {

/// Below this ratio of its smallest to its largest extent an indefinite matrix is put down to
/// the body's thinness rather than the weights (a 1 x 1 x 1e-9 plate fails; 1e-3 solves).
inline constexpr double kThinnestBody = 1e-6;

/// The case's problem for an indefinite matrix that the solver part `found` (its message)
/// reported. `used` carries the weights as used (c3 chosen when "auto"); `coarse` and `data`
/// give c3's limit on the case's uniform levels when c3 was given by hand.
template <int dim>
CaseException indefinite_weights(const CaseSpec& used, const SimplexMesh<dim>& coarse,
                                 const ProblemData<dim>& data, const std::string& found);

}  // namespace fosls
