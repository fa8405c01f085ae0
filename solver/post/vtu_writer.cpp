#include "post/vtu_writer.hpp"

#include <cmath>
#include <sstream>

#include "post/fe_field.hpp"

namespace fosls {

std::string write_vtu(const FoslsAssembler& assembler, const AssembledProblem& problem,
                      const Vector& x_full, const FunctionalParts& functional) {
  const FoslsSpace& space = assembler.space();
  const Mesh& mesh = space.mesh();
  const FeField field(space, x_full, problem.stress_scale);
  const ElasticMaterial& mat = assembler.data().material;
  // Plane strain: σ_zz = λ/(2(λ+μ)) tr σ, which is tr σ / 2 for λ = ∞.
  const double kappa = mat.incompressible() ? 0.5 : mat.lambda / (2.0 * (mat.lambda + mat.mu));
  std::ostringstream o;
  o.precision(12);
  o << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << mesh.num_vertices()
    << "\" NumberOfCells=\"" << mesh.num_triangles() << "\">\n<Points>\n"
    << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : mesh.vertices()) o << p.x() << ' ' << p.y() << " 0\n";
  o << "</DataArray>\n</Points>\n<Cells>\n"
    << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangle(t);
    o << tri[0] << ' ' << tri[1] << ' ' << tri[2] << '\n';
  }
  o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
  for (int t = 0; t < mesh.num_triangles(); ++t) o << 3 * (t + 1) << '\n';
  o << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int t = 0; t < mesh.num_triangles(); ++t) o << "5\n";
  o << "</DataArray>\n</Cells>\n<PointData Vectors=\"u\">\n"
    << "<DataArray type=\"Float64\" Name=\"u\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int v = 0; v < mesh.num_vertices(); ++v)
    o << field.cartesian(space.u_dof(v, 0)) << ' ' << field.cartesian(space.u_dof(v, 1)) << " 0\n";
  o << "</DataArray>\n</PointData>\n<CellData Scalars=\"von_mises\">\n"
    << "<DataArray type=\"Float64\" Name=\"sigma\" NumberOfComponents=\"4\" format=\"ascii\">\n";
  std::vector<double> von_mises(mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangle(t);
    const Point c = (mesh.vertex(tri[0]) + mesh.vertex(tri[1]) + mesh.vertex(tri[2])) / 3.0;
    const Eigen::Matrix2d s = field.sigma(t, c);
    o << s(0, 0) << ' ' << s(0, 1) << ' ' << s(1, 0) << ' ' << s(1, 1) << '\n';
    const double sxx = s(0, 0), syy = s(1, 1), sxy = 0.5 * (s(0, 1) + s(1, 0));
    const double szz = kappa * (sxx + syy);
    von_mises[t] = std::sqrt(
        0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
        3.0 * sxy * sxy);
  }
  o << "</DataArray>\n<DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n";
  for (double v : von_mises) o << v << '\n';
  o << "</DataArray>\n<DataArray type=\"Float64\" Name=\"functional\" format=\"ascii\">\n";
  for (double v : functional.element) o << v << '\n';
  o << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return o.str();
}

}  // namespace fosls
