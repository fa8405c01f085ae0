#include "post/strain_measure.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "post/fe_field.hpp"

namespace fosls {

StrainPeak largest_strain(const FoslsAssembler<2>& assembler, const AssembledProblem& problem,
                          const Vector& x_full, double area_fraction) {
  const FoslsSpace<2>& space = assembler.space();
  const Mesh& mesh = space.mesh();
  const FeField field(space, x_full, problem.stress_scale);
  StrainPeak peak;
  std::vector<std::pair<double, double>> strain_area;  // per triangle
  double total = 0.0;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangle(t);
    const Point c = (mesh.vertex(tri[0]) + mesh.vertex(tri[1]) + mesh.vertex(tri[2])) / 3.0;
    const Eigen::Matrix2d g = field.grad_u(t, c);
    const double exx = g(0, 0), eyy = g(1, 1), exy = 0.5 * (g(0, 1) + g(1, 0));
    const double mean = (exx + eyy) / 3.0;  // ε_zz = 0 in plane strain
    const double dxx = exx - mean, dyy = eyy - mean, dzz = -mean;
    const double e = std::sqrt(2.0 / 3.0 * (dxx * dxx + dyy * dyy + dzz * dzz + 2.0 * exy * exy));
    if (e > peak.largest) peak.largest = e, peak.where = c;
    strain_area.push_back({e, mesh.triangle_area(t)});
    total += mesh.triangle_area(t);
  }
  std::sort(strain_area.begin(), strain_area.end(), std::greater<>());
  double area = 0.0;
  for (const auto& [e, a] : strain_area) {
    peak.strain = e;
    if ((area += a) >= area_fraction * total) break;
  }
  return peak;
}

}  // namespace fosls
