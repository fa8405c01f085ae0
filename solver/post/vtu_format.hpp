#pragma once
// The VTK XML unstructured-grid format both .vtu writers share (vtu_writer.hpp for triangles,
// tet_vtu_writer.hpp for tetrahedra): the array descriptions, the two encodings, the grid's
// points and cells, and the data arrays themselves.

#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

#include "post/base64.hpp"

namespace fosls {

/// One data array of a VTU file.
struct VtuArray {
  const char* name;
  bool point_data;                      ///< per vertex (else per cell)
  std::vector<const char*> components;  ///< component names; empty for a scalar
  const char* unit;                     ///< "L" (length), "S" (stress), "1", ...
  const char* meaning;
  /// The VTK type of the binary form: Float32 for the stresses and the functional (7 digits
  /// are all a plot shows), UInt8 and Int32 for flags and counts; the ASCII form is Float64.
  const char* binary_type = "Float64";
};

/// How the arrays are written: "binary" is base64 of a UInt32 byte count followed by the
/// little-endian values (VTK's inline binary format, exact doubles, about 40 % of the ASCII
/// size); "ascii" is text with 12 significant digits.
enum class VtuEncoding { kBinary, kAscii };

/// One DataArray element: `type` is the VTK type name of T, `attributes` what follows it.
template <class T>
void write_data_array(std::ostream& o, const char* type, const std::string& attributes,
                      const std::vector<T>& values, std::size_t per_line, VtuEncoding encoding) {
  o << "<DataArray type=\"" << type << "\"" << attributes << " format=\""
    << (encoding == VtuEncoding::kAscii ? "ascii" : "binary") << "\">\n";
  if (encoding == VtuEncoding::kAscii) {
    for (std::size_t i = 0; i < values.size(); ++i)
      o << +values[i] << (i % per_line + 1 == per_line ? '\n' : ' ');
  } else {
    // VTK's inline binary: base64 of the byte count (UInt32) and the values, encoded as one
    // stream (the reader seeks past the header inside the decoded bytes).
    const std::uint32_t bytes = static_cast<std::uint32_t>(values.size() * sizeof(T));
    std::string raw(sizeof bytes + bytes, '\0');
    std::memcpy(raw.data(), &bytes, sizeof bytes);
    if (bytes) std::memcpy(raw.data() + sizeof bytes, values.data(), bytes);
    std::string text;
    append_base64(text, raw.data(), raw.size());
    o << text << '\n';
  }
  o << "</DataArray>\n";
}

/// A described array (components per tuple as in its description), in its binary type.
void write_array(std::ostream& o, const VtuArray& a, const std::vector<double>& values,
                 VtuEncoding encoding);

/// The file up to the point data: header, points (x, y, z per vertex) and cells (`per_cell`
/// vertices each, all of VTK type `cell_type`).
void write_grid(std::ostream& o, const std::vector<double>& points,
                const std::vector<std::int32_t>& connectivity, int per_cell, std::uint8_t cell_type,
                VtuEncoding encoding);

/// The end of the file after the cell data.
void write_grid_end(std::ostream& o);

}  // namespace fosls
