#pragma once
// The size of the strain a solution has: linear elasticity holds for small strains only, and
// a result whose strains reach several per cent says so (case/result/result_warnings.hpp).

#include "assembly/fosls_assembler.hpp"
#include "mesh/mesh.hpp"

namespace fosls {

struct StrainPeak {
  /// The von Mises equivalent strain √(2/3 e:e) (e = dev ε) reached or exceeded on
  /// `area_fraction` of the body's area: a singular corner, whose largest strain grows with
  /// every refinement on a vanishing area, does not set it.
  double strain = 0.0;
  double largest = 0.0;         ///< the largest over the triangles
  Point where = Point::Zero();  ///< the centroid of the triangle with the largest
};

/// ε = sym ∇u of the P1 displacement (constant per triangle; plane strain, ε_zz = 0) and its
/// equivalent strain over the triangles.
StrainPeak largest_strain(const FoslsAssembler<2>& assembler, const AssembledProblem& problem,
                          const Vector& x_full, double area_fraction = 0.01);

}  // namespace fosls
