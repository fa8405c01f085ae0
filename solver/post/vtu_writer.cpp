#include "post/vtu_writer.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

#include "post/base64.hpp"
#include "post/fe_field.hpp"

namespace fosls {

namespace {

const std::vector<VtuArray>& array_table() {
  static const std::vector<VtuArray> table = {
      {"u", true, {"x", "y", "z"}, "L", "displacement (z = 0: plane strain)"},
      {"contact_boundary",
       true,
       {},
       "1",
       "1 at the vertices of contact edges, 0 elsewhere",
       "UInt8"},
      {"contact_pressure",
       true,
       {},
       "S",
       "contact pressure p = −σ_nn ≥ 0 at a contact vertex (the mean of its contact edges), 0 "
       "elsewhere"},
      {"contact_shear",
       true,
       {},
       "S",
       "tangential traction σ_nt at a contact vertex (the mean of its contact edges; t = (−n_y, "
       "n_x)), 0 elsewhere and on frictionless contact"},
      {"contact_state",
       true,
       {},
       "1",
       "at a contact vertex the largest state of its contact edges: 0 open, 1 stick, 2 slip "
       "(frictionless contact in contact slips); 0 elsewhere",
       "UInt8"},
      {"gap",
       true,
       {},
       "L",
       "remaining gap g − u·n along the constraint direction at a contact vertex (0 where "
       "closed), 0 elsewhere"},
      {"sigma_nodal",
       true,
       {"xx", "xy", "yx", "yy"},
       "S",
       "stress tensor at the vertex, row by row: the mean over the vertex's triangles of each "
       "triangle's (linear) RT0 stress evaluated at the vertex, weighted by the triangles' "
       "areas (nodal averaging, for smooth plots; the cell array sigma is the discrete field)",
       "Float32"},
      {"von_mises_nodal",
       true,
       {},
       "S",
       "von Mises stress at the vertex: the area-weighted mean of each adjacent triangle's von "
       "Mises stress at the vertex (computed before averaging, so it is not lowered where the "
       "triangles' stresses differ)",
       "Float32"},
      {"sigma",
       false,
       {"xx", "xy", "yx", "yy"},
       "S",
       "stress tensor at the centroid, row by row (each row is an RT0 field, so σ_xy and σ_yx "
       "differ by the discretisation error)",
       "Float32"},
      {"von_mises",
       false,
       {},
       "S",
       "von Mises stress at the centroid (plane strain: σ_zz from λ)",
       "Float32"},
      {"functional",
       false,
       {},
       "scaled",
       "the triangle's share of the FOSLS functional J (its error indicator η_T², which "
       "drives adaptive refinement), in the scaled units of the result's functional",
       "Float32"},
      {"generation",
       false,
       {},
       "1",
       "refinement level of the triangle: bisections from its coarse-mesh ancestor (a uniform "
       "refinement counts as two)",
       "Int32"},
  };
  return table;
}

const VtuArray& info(const std::string& name) {
  for (const auto& a : array_table())
    if (name == a.name) return a;
  throw std::logic_error("write_vtu writes an array missing from vtu_arrays(): " + name);
}

/// The attributes after the name: components and their names.
std::string component_attributes(const VtuArray& a) {
  if (a.components.empty()) return "";
  std::string s = " NumberOfComponents=\"" + std::to_string(a.components.size()) + "\"";
  for (std::size_t c = 0; c < a.components.size(); ++c)
    s += " ComponentName" + std::to_string(c) + "=\"" + a.components[c] + "\"";
  return s;
}

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

/// A named array of vtu_arrays() (components per tuple as in its table entry).
void write_array(std::ostream& o, const std::string& name, const std::vector<double>& values,
                 VtuEncoding encoding) {
  const VtuArray& a = info(name);
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

/// Plane strain: σ_zz = κ tr σ with κ = λ/(2(λ+μ)), which is ½ for λ = ∞.
double von_mises(const Eigen::Matrix2d& s, double kappa) {
  const double sxx = s(0, 0), syy = s(1, 1), sxy = 0.5 * (s(0, 1) + s(1, 0));
  const double szz = kappa * (sxx + syy);
  return std::sqrt(
      0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
      3.0 * sxy * sxy);
}

/// Stresses per triangle (at the centroid) and per vertex (area-weighted means of the
/// triangles' values at the vertex).
struct StressArrays {
  std::vector<double> sigma, von_mises, sigma_nodal, von_mises_nodal;
};

StressArrays stress_arrays(const Mesh& mesh, const FeField& field, double kappa) {
  const int nv = mesh.num_vertices(), nt = mesh.num_triangles();
  StressArrays a;
  a.sigma.resize(4 * nt), a.von_mises.resize(nt);
  a.sigma_nodal.assign(4 * nv, 0.0), a.von_mises_nodal.assign(nv, 0.0);
  std::vector<double> weight(nv, 0.0);
  for (int t = 0; t < nt; ++t) {
    const auto& tri = mesh.triangle(t);
    const Point c = (mesh.vertex(tri[0]) + mesh.vertex(tri[1]) + mesh.vertex(tri[2])) / 3.0;
    const Eigen::Matrix2d s = field.sigma(t, c);
    for (int k = 0; k < 4; ++k) a.sigma[4 * t + k] = s(k / 2, k % 2);
    a.von_mises[t] = von_mises(s, kappa);
    const double area = mesh.triangle_area(t);
    for (int v : tri) {
      const Eigen::Matrix2d sv = field.sigma(t, mesh.vertex(v));
      for (int k = 0; k < 4; ++k) a.sigma_nodal[4 * v + k] += area * sv(k / 2, k % 2);
      a.von_mises_nodal[v] += area * von_mises(sv, kappa);
      weight[v] += area;
    }
  }
  for (int v = 0; v < nv; ++v) {
    if (weight[v] <= 0.0) continue;
    for (int k = 0; k < 4; ++k) a.sigma_nodal[4 * v + k] /= weight[v];
    a.von_mises_nodal[v] /= weight[v];
  }
  return a;
}

}  // namespace

std::span<const VtuArray> vtu_arrays() { return array_table(); }

std::string write_vtu(const FoslsAssembler& assembler, const AssembledProblem& problem,
                      const Vector& x_full, const FunctionalParts& functional,
                      const ContactResult& contact, const std::vector<int>& generation,
                      VtuEncoding encoding) {
  const FoslsSpace& space = assembler.space();
  const Mesh& mesh = space.mesh();
  const FeField field(space, x_full, problem.stress_scale);
  const ElasticMaterial& mat = assembler.data().material;
  const double kappa = mat.incompressible() ? 0.5 : mat.lambda / (2.0 * (mat.lambda + mat.mu));
  const int nv = mesh.num_vertices(), nt = mesh.num_triangles();

  std::vector<double> points(3 * nv, 0.0), u(3 * nv, 0.0), on_contact(nv, 0.0), pressure(nv, 0.0),
      shear(nv, 0.0), state(nv, 0.0), gap(nv, 0.0);
  for (int v = 0; v < nv; ++v) {
    points[3 * v] = mesh.vertex(v).x(), points[3 * v + 1] = mesh.vertex(v).y();
    u[3 * v] = field.cartesian(space.u_dof(v, 0));
    u[3 * v + 1] = field.cartesian(space.u_dof(v, 1));
  }
  for (const auto& r : contact.vertices) {
    on_contact[r.vertex] = 1.0;
    pressure[r.vertex] = r.pressure;
    shear[r.vertex] = r.shear;
    state[r.vertex] = r.state;
    gap[r.vertex] = r.gap;
  }
  std::vector<std::int32_t> connectivity(3 * nt), offsets(nt);
  for (int t = 0; t < nt; ++t) {
    for (int k = 0; k < 3; ++k) connectivity[3 * t + k] = mesh.triangle(t)[k];
    offsets[t] = 3 * (t + 1);
  }
  const std::vector<std::uint8_t> types(nt, 5);  // VTK_TRIANGLE
  const StressArrays stress = stress_arrays(mesh, field, kappa);

  std::ostringstream o;
  o.precision(12);
  o << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
       "header_type=\"UInt32\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << nv << "\" NumberOfCells=\"" << nt
    << "\">\n<Points>\n";
  write_data_array(o, "Float64", " NumberOfComponents=\"3\"", points, 3, encoding);
  o << "</Points>\n<Cells>\n";
  write_data_array(o, "Int32", " Name=\"connectivity\"", connectivity, 3, encoding);
  write_data_array(o, "Int32", " Name=\"offsets\"", offsets, 1, encoding);
  write_data_array(o, "UInt8", " Name=\"types\"", types, 1, encoding);
  // No Tensors attribute: VTK's takes 9 (or 6) components, σ has 4 (it warned on every read).
  o << "</Cells>\n<PointData Vectors=\"u\" Scalars=\"contact_pressure\">\n";
  write_array(o, "u", u, encoding);
  write_array(o, "contact_boundary", on_contact, encoding);
  write_array(o, "contact_pressure", pressure, encoding);
  write_array(o, "contact_shear", shear, encoding);
  write_array(o, "contact_state", state, encoding);
  write_array(o, "gap", gap, encoding);
  write_array(o, "sigma_nodal", stress.sigma_nodal, encoding);
  write_array(o, "von_mises_nodal", stress.von_mises_nodal, encoding);
  o << "</PointData>\n<CellData Scalars=\"von_mises\">\n";
  write_array(o, "sigma", stress.sigma, encoding);
  write_array(o, "von_mises", stress.von_mises, encoding);
  write_array(o, "functional", functional.element, encoding);
  write_array(o, "generation", std::vector<double>(generation.begin(), generation.end()), encoding);
  o << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return o.str();
}

}  // namespace fosls
