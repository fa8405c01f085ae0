#include "post/vtu_writer.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

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

/// A named array of vtu_arrays().
void write_array(std::ostream& o, const std::string& name, const std::vector<double>& values,
                 VtuEncoding encoding) {
  write_array(o, info(name), values, encoding);
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

std::string write_vtu(const FoslsAssembler<2>& assembler, const AssembledProblem& problem,
                      const Vector& x_full, const FunctionalParts& functional,
                      const ContactResult& contact, const std::vector<int>& generation,
                      VtuEncoding encoding) {
  const FoslsSpace<2>& space = assembler.space();
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
  std::vector<std::int32_t> connectivity(3 * nt);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) connectivity[3 * t + k] = mesh.triangle(t)[k];
  const StressArrays stress = stress_arrays(mesh, field, kappa);

  std::ostringstream o;
  o.precision(12);
  write_grid(o, points, connectivity, 3, 5, encoding);  // VTK_TRIANGLE
  // No Tensors attribute: VTK's takes 9 (or 6) components, σ has 4 (it warned on every read).
  o << "<PointData Vectors=\"u\" Scalars=\"contact_pressure\">\n";
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
  o << "</CellData>\n";
  write_grid_end(o);
  return o.str();
}

}  // namespace fosls
