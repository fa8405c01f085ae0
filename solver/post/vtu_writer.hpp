#pragma once
// VTK XML unstructured grid (.vtu) of a 2D solution for ParaView: binary (base64, inline) by
// default, ASCII on request (vtu_format.hpp). The arrays it writes are listed, with their units and
// meaning, by vtu_arrays() (documented in docs/result-format.md).

#include <span>
#include <string>
#include <vector>

#include "assembly/fosls_assembler.hpp"
#include "post/contact_output.hpp"
#include "post/vtu_format.hpp"

namespace fosls {

/// Every array write_vtu writes, in the order of the file.
std::span<const VtuArray> vtu_arrays();

/// `generation`: per triangle, the bisections that separate it from its coarse-mesh ancestor
/// (a red refinement counts as two).
std::string write_vtu(const FoslsAssembler<2>& assembler, const AssembledProblem& problem,
                      const Vector& x_full, const FunctionalParts& functional,
                      const ContactResult& contact, const std::vector<int>& generation,
                      VtuEncoding encoding = VtuEncoding::kBinary);

}  // namespace fosls
