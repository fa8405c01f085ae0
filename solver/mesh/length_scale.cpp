#include "mesh/length_scale.hpp"

#include <cmath>

namespace fosls {

double length_scale(const Mesh& mesh) {
  double area = 0.0;
  for (int t = 0; t < mesh.num_triangles(); ++t) area += mesh.triangle_area(t);
  if (!(area > 0.0) || !std::isfinite(area)) return 1.0;
  return std::pow(10.0, std::round(std::log10(std::sqrt(area))));
}

double length_scale(const TetMesh& mesh) {
  double volume = 0.0;
  for (int t = 0; t < mesh.num_tets(); ++t) volume += mesh.tet_volume(t);
  if (!(volume > 0.0) || !std::isfinite(volume)) return 1.0;
  return std::pow(10.0, std::round(std::log10(std::cbrt(volume))));
}

}  // namespace fosls
