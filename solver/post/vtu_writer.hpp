#pragma once
// VTK XML unstructured grid (.vtu, ASCII) of a solution for ParaView: point data u, cell data
// σ (at the centroid), von Mises stress (plane strain) and the element functional.

#include <string>

#include "assembly/fosls_assembler.hpp"

namespace fosls {

std::string write_vtu(const FoslsAssembler& assembler, const AssembledProblem& problem,
                      const Vector& x_full, const FunctionalParts& functional);

}  // namespace fosls
