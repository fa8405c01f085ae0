#include "post/vtu_format.hpp"

namespace fosls {

namespace {

/// The attributes after the name: components and their names.
std::string component_attributes(const VtuArray& a) {
  if (a.components.empty()) return "";
  std::string s = " NumberOfComponents=\"" + std::to_string(a.components.size()) + "\"";
  for (std::size_t c = 0; c < a.components.size(); ++c)
    s += " ComponentName" + std::to_string(c) + "=\"" + a.components[c] + "\"";
  return s;
}

}  // namespace

void write_array(std::ostream& o, const VtuArray& a, const std::vector<double>& values,
                 VtuEncoding encoding) {
  const std::size_t n = a.components.empty() ? 1 : a.components.size();
  const std::string attributes = " Name=\"" + std::string(a.name) + "\"" + component_attributes(a);
  const std::string type = encoding == VtuEncoding::kAscii ? "Float64" : a.binary_type;
  auto as = [&values](auto zero) {
    return std::vector<decltype(zero)>(values.begin(), values.end());
  };
  if (type == "Float32")
    write_data_array(o, "Float32", attributes, as(0.0f), n, encoding);
  else if (type == "UInt8")
    write_data_array(o, "UInt8", attributes, as(std::uint8_t{0}), n, encoding);
  else if (type == "Int32")
    write_data_array(o, "Int32", attributes, as(std::int32_t{0}), n, encoding);
  else
    write_data_array(o, "Float64", attributes, values, n, encoding);
}

void write_grid(std::ostream& o, const std::vector<double>& points,
                const std::vector<std::int32_t>& connectivity, int per_cell, std::uint8_t cell_type,
                VtuEncoding encoding) {
  const std::size_t nv = points.size() / 3, nc = connectivity.size() / per_cell;
  std::vector<std::int32_t> offsets(nc);
  for (std::size_t c = 0; c < nc; ++c) offsets[c] = static_cast<std::int32_t>(per_cell * (c + 1));
  const std::vector<std::uint8_t> types(nc, cell_type);
  o << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
       "header_type=\"UInt32\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << nv << "\" NumberOfCells=\"" << nc
    << "\">\n<Points>\n";
  write_data_array(o, "Float64", " NumberOfComponents=\"3\"", points, 3, encoding);
  o << "</Points>\n<Cells>\n";
  write_data_array(o, "Int32", " Name=\"connectivity\"", connectivity, per_cell, encoding);
  write_data_array(o, "Int32", " Name=\"offsets\"", offsets, 1, encoding);
  write_data_array(o, "UInt8", " Name=\"types\"", types, 1, encoding);
  o << "</Cells>\n";
}

void write_grid_end(std::ostream& o) { o << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n"; }

}  // namespace fosls
