#include "post/tet_vtu_writer.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fem/simplex_element.hpp"
#include "post/contact_force.hpp"

namespace fosls {

namespace {

const std::vector<VtuArray>& array_table() {
  static const std::vector<VtuArray> table = {
      {"u", true, {"x", "y", "z"}, "L", "displacement"},
      {"contact_boundary",
       true,
       {},
       "1",
       "1 at the vertices of contact faces, 0 elsewhere",
       "UInt8"},
      {"contact_pressure",
       true,
       {},
       "S",
       "contact pressure p = −σ_nn ≥ 0 at a contact vertex (the mean of its contact faces' "
       "constant RT0 values), 0 elsewhere"},
      {"sigma",
       false,
       {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"},
       "S",
       "stress tensor at the centroid, row by row (each row is an RT0 field, so σ_ij and σ_ji "
       "differ by the discretisation error)",
       "Float32"},
      {"von_mises",
       false,
       {},
       "S",
       "von Mises stress of σ's symmetric part at the centroid",
       "Float32"},
      {"functional",
       false,
       {},
       "scaled",
       "the tetrahedron's share of the FOSLS functional J (with the contact term of its contact "
       "faces), in the assembler's scaled units",
       "Float32"},
  };
  return table;
}

void write_named(std::ostream& o, const std::string& name, const std::vector<double>& values,
                 VtuEncoding encoding) {
  for (const VtuArray& a : array_table())
    if (name == a.name) return write_array(o, a, values, encoding);
  throw std::logic_error("write_tet_vtu writes an array missing from tet_vtu_arrays(): " + name);
}

double von_mises(const Eigen::Matrix3d& sigma) {
  const Eigen::Matrix3d sym = 0.5 * (sigma + sigma.transpose());
  const Eigen::Matrix3d dev = sym - sym.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * dev.squaredNorm());
}

/// The stress of tetrahedron t at x from Cartesian DOFs: row i is Σ_k S_{f_k, i} ψ_k(x).
Eigen::Matrix3d stress_at(const FoslsSpace<3>& space, const Vector& cartesian, int t,
                          const Point3& x) {
  const TetMesh& mesh = space.mesh();
  const SimplexElement<3> e(mesh, t);
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 4; ++k) {
    const Point3 psi = e.rt0(k, x);
    for (int i = 0; i < 3; ++i)
      sigma.row(i) += cartesian[space.sigma_dof(mesh.tet_face(t, k), i)] * psi.transpose();
  }
  return sigma;
}

}  // namespace

std::span<const VtuArray> tet_vtu_arrays() { return array_table(); }

std::string write_tet_vtu(const FoslsAssembler<3>& assembler, const AssembledProblem& problem,
                          const Vector& x_full, VtuEncoding encoding) {
  const FoslsSpace<3>& space = assembler.space();
  const TetMesh& mesh = space.mesh();
  const Vector cartesian = space.rotation() * x_full;  // contact frames back to x, y, z
  const int nv = mesh.num_vertices(), nt = mesh.num_tets();
  std::vector<double> points(3 * nv), u(3 * nv), on_contact(nv, 0.0), pressure(nv, 0.0);
  for (int v = 0; v < nv; ++v)
    for (int c = 0; c < 3; ++c) {
      points[3 * v + c] = mesh.vertex(v)[c];
      u[3 * v + c] = cartesian[space.u_dof(v, c)];
    }
  const std::vector<double> face_pressure = contact_pressure(space, x_full, problem.stress_scale);
  std::vector<int> faces(nv, 0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (space.is_contact_facet(f))
      for (int v : mesh.face(f)) {
        on_contact[v] = 1.0;
        pressure[v] += face_pressure[f];
        ++faces[v];
      }
  for (int v = 0; v < nv; ++v)
    if (faces[v] > 0) pressure[v] /= faces[v];
  std::vector<std::int32_t> connectivity(4 * nt);
  std::vector<double> sigma(9 * nt), mises(nt);
  for (int t = 0; t < nt; ++t) {
    Point3 centroid = Point3::Zero();
    for (int k = 0; k < 4; ++k) {
      connectivity[4 * t + k] = mesh.tet(t)[k];
      centroid += 0.25 * mesh.vertex(mesh.tet(t)[k]);
    }
    const Eigen::Matrix3d s = problem.stress_scale * stress_at(space, cartesian, t, centroid);
    for (int k = 0; k < 9; ++k) sigma[9 * t + k] = s(k / 3, k % 3);
    mises[t] = von_mises(s);
  }
  std::ostringstream o;
  o.precision(12);
  write_grid(o, points, connectivity, 4, 10, encoding);  // VTK_TETRA
  o << "<PointData Vectors=\"u\" Scalars=\"contact_pressure\">\n";
  write_named(o, "u", u, encoding);
  write_named(o, "contact_boundary", on_contact, encoding);
  write_named(o, "contact_pressure", pressure, encoding);
  o << "</PointData>\n<CellData Scalars=\"von_mises\" Tensors=\"sigma\">\n";
  write_named(o, "sigma", sigma, encoding);
  write_named(o, "von_mises", mises, encoding);
  write_named(o, "functional", assembler.functional(x_full).element, encoding);
  o << "</CellData>\n";
  write_grid_end(o);
  return o.str();
}

}  // namespace fosls
