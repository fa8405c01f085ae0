#pragma once
// VTK XML unstructured grid (.vtu) of a 3D solution for ParaView (stage 3 of the 3D track, so
// far written by fosls-bench-3d): tetrahedra, the displacement and the contact pressure at the
// vertices, the stress, von Mises stress and the functional per tetrahedron. The arrays are
// listed, with their units and meaning, by tet_vtu_arrays().

#include <span>
#include <string>

#include "assembly/fosls_assembler.hpp"
#include "post/vtu_format.hpp"

namespace fosls {

/// Every array write_tet_vtu writes, in the order of the file.
std::span<const VtuArray> tet_vtu_arrays();

/// The solution x_full (the full DOF vector, contact DOFs in their rotated frames) of
/// `problem` as a .vtu file.
std::string write_tet_vtu(const FoslsAssembler<3>& assembler, const AssembledProblem& problem,
                          const Vector& x_full, VtuEncoding encoding = VtuEncoding::kBinary);

}  // namespace fosls
