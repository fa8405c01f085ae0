#pragma once
// VTK XML unstructured grid (.vtu, ASCII) of a solution for ParaView. The arrays it writes are
// listed, with their units and meaning, by vtu_arrays() (documented in docs/result-format.md).

#include <span>
#include <string>
#include <vector>

#include "assembly/fosls_assembler.hpp"
#include "post/contact_output.hpp"

namespace fosls {

/// One data array of the VTU file.
struct VtuArray {
  const char* name;
  bool point_data;                      ///< per vertex (else per triangle)
  std::vector<const char*> components;  ///< component names; empty for a scalar
  const char* unit;                     ///< "L" (length), "S" (stress), "1", ...
  const char* meaning;
};

/// Every array write_vtu writes, in the order of the file.
std::span<const VtuArray> vtu_arrays();

/// `generation`: per triangle, the bisections that separate it from its coarse-mesh ancestor
/// (a red refinement counts as two).
std::string write_vtu(const FoslsAssembler& assembler, const AssembledProblem& problem,
                      const Vector& x_full, const FunctionalParts& functional,
                      const ContactResult& contact, const std::vector<int>& generation);

}  // namespace fosls
