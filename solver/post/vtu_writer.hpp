#pragma once
// VTK XML unstructured grid (.vtu) of a solution for ParaView: binary (base64, inline) by
// default, ASCII on request. The arrays it writes are listed, with their units and meaning, by
// vtu_arrays() (documented in docs/result-format.md).

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
  /// The VTK type of the binary form: Float32 for the stresses and the functional (7 digits
  /// are all a plot shows), UInt8 and Int32 for flags and counts; the ASCII form is Float64.
  const char* binary_type = "Float64";
};

/// Every array write_vtu writes, in the order of the file.
std::span<const VtuArray> vtu_arrays();

/// How the arrays are written: "binary" is base64 of a UInt32 byte count followed by the
/// little-endian values (VTK's inline binary format, exact doubles, about 40 % of the ASCII
/// size); "ascii" is text with 12 significant digits.
enum class VtuEncoding { kBinary, kAscii };

/// `generation`: per triangle, the bisections that separate it from its coarse-mesh ancestor
/// (a red refinement counts as two).
std::string write_vtu(const FoslsAssembler& assembler, const AssembledProblem& problem,
                      const Vector& x_full, const FunctionalParts& functional,
                      const ContactResult& contact, const std::vector<int>& generation,
                      VtuEncoding encoding = VtuEncoding::kBinary);

}  // namespace fosls
