#include "post/vtu_writer.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "post/fe_field.hpp"

namespace fosls {

namespace {

const std::vector<VtuArray>& array_table() {
  static const std::vector<VtuArray> table = {
      {"u", true, {"x", "y", "z"}, "L", "displacement (z = 0: plane strain)"},
      {"contact_boundary", true, {}, "1", "1 at the vertices of contact edges, 0 elsewhere"},
      {"contact_pressure",
       true,
       {},
       "S",
       "contact pressure p = −σ_nn ≥ 0 at a contact vertex (the mean of its contact edges), 0 "
       "elsewhere"},
      {"gap",
       true,
       {},
       "L",
       "remaining gap g − u·n along the constraint direction at a contact vertex (0 where "
       "closed), 0 elsewhere"},
      {"sigma",
       false,
       {"xx", "xy", "yx", "yy"},
       "S",
       "stress tensor at the centroid, row by row (each row is an RT0 field, so σ_xy and σ_yx "
       "differ by the discretisation error)"},
      {"von_mises", false, {}, "S", "von Mises stress at the centroid (plane strain: σ_zz from λ)"},
      {"functional",
       false,
       {},
       "scaled",
       "the triangle's share of the FOSLS functional J (its error indicator η_T², which "
       "drives adaptive refinement), in the scaled units of the result's functional"},
      {"generation",
       false,
       {},
       "1",
       "refinement level of the triangle: bisections from its coarse-mesh ancestor (a uniform "
       "refinement counts as two)"},
  };
  return table;
}

const VtuArray& info(const std::string& name) {
  for (const auto& a : array_table())
    if (name == a.name) return a;
  throw std::logic_error("write_vtu writes an array missing from vtu_arrays(): " + name);
}

/// Writes one DataArray of `values` (components per tuple as in its table entry).
void write_array(std::ostream& o, const std::string& name, const std::vector<double>& values) {
  const VtuArray& a = info(name);
  const std::size_t n = a.components.empty() ? 1 : a.components.size();
  o << "<DataArray type=\"Float64\" Name=\"" << a.name << "\"";
  if (n > 1) {
    o << " NumberOfComponents=\"" << n << "\"";
    for (std::size_t c = 0; c < n; ++c)
      o << " ComponentName" << c << "=\"" << a.components[c] << "\"";
  }
  o << " format=\"ascii\">\n";
  for (std::size_t i = 0; i < values.size(); ++i) o << values[i] << (i % n + 1 == n ? '\n' : ' ');
  o << "</DataArray>\n";
}

}  // namespace

std::span<const VtuArray> vtu_arrays() { return array_table(); }

std::string write_vtu(const FoslsAssembler& assembler, const AssembledProblem& problem,
                      const Vector& x_full, const FunctionalParts& functional,
                      const ContactResult& contact, const std::vector<int>& generation) {
  const FoslsSpace& space = assembler.space();
  const Mesh& mesh = space.mesh();
  const FeField field(space, x_full, problem.stress_scale);
  const ElasticMaterial& mat = assembler.data().material;
  // Plane strain: σ_zz = λ/(2(λ+μ)) tr σ, which is tr σ / 2 for λ = ∞.
  const double kappa = mat.incompressible() ? 0.5 : mat.lambda / (2.0 * (mat.lambda + mat.mu));
  const int nv = mesh.num_vertices(), nt = mesh.num_triangles();

  std::vector<double> u(3 * nv, 0.0), on_contact(nv, 0.0), pressure(nv, 0.0), gap(nv, 0.0);
  for (int v = 0; v < nv; ++v) {
    u[3 * v] = field.cartesian(space.u_dof(v, 0));
    u[3 * v + 1] = field.cartesian(space.u_dof(v, 1));
  }
  for (const auto& r : contact.vertices) {
    on_contact[r.vertex] = 1.0;
    pressure[r.vertex] = r.pressure;
    gap[r.vertex] = r.gap;
  }
  std::vector<double> sigma(4 * nt), von_mises(nt);
  for (int t = 0; t < nt; ++t) {
    const auto& tri = mesh.triangle(t);
    const Point c = (mesh.vertex(tri[0]) + mesh.vertex(tri[1]) + mesh.vertex(tri[2])) / 3.0;
    const Eigen::Matrix2d s = field.sigma(t, c);
    sigma[4 * t] = s(0, 0), sigma[4 * t + 1] = s(0, 1);
    sigma[4 * t + 2] = s(1, 0), sigma[4 * t + 3] = s(1, 1);
    const double sxx = s(0, 0), syy = s(1, 1), sxy = 0.5 * (s(0, 1) + s(1, 0));
    const double szz = kappa * (sxx + syy);
    von_mises[t] = std::sqrt(
        0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
        3.0 * sxy * sxy);
  }

  std::ostringstream o;
  o.precision(12);
  o << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << nv << "\" NumberOfCells=\"" << nt
    << "\">\n<Points>\n"
    << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : mesh.vertices()) o << p.x() << ' ' << p.y() << " 0\n";
  o << "</DataArray>\n</Points>\n<Cells>\n"
    << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (int t = 0; t < nt; ++t) {
    const auto& tri = mesh.triangle(t);
    o << tri[0] << ' ' << tri[1] << ' ' << tri[2] << '\n';
  }
  o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  for (int t = 0; t < nt; ++t) o << 3 * (t + 1) << '\n';
  o << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int t = 0; t < nt; ++t) o << "5\n";
  o << "</DataArray>\n</Cells>\n<PointData Vectors=\"u\" Scalars=\"contact_pressure\">\n";
  write_array(o, "u", u);
  write_array(o, "contact_boundary", on_contact);
  write_array(o, "contact_pressure", pressure);
  write_array(o, "gap", gap);
  o << "</PointData>\n<CellData Tensors=\"sigma\" Scalars=\"von_mises\">\n";
  write_array(o, "sigma", sigma);
  write_array(o, "von_mises", von_mises);
  write_array(o, "functional", functional.element);
  write_array(o, "generation", std::vector<double>(generation.begin(), generation.end()));
  o << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return o.str();
}

}  // namespace fosls
