#pragma once
// Large inputs of the hostile-use probes, written as gmsh 4.1 text: a fine grid of the unit
// square (megabytes of valid mesh), and the smallest 2D and 3D meshes with as many more physical
// names as asked (megabytes of names).

#include <array>
#include <functional>
#include <sstream>
#include <string>
#include <utility>

namespace fosls::service::testing {

/// The unit square as an n × n grid of triangle pairs, with the boundary groups "bottom",
/// "right", "top" and "left": about 70 bytes per grid cell.
inline std::string grid_msh(int n) {
  const int m = n + 1;
  auto node = [m](int i, int j) { return j * m + i + 1; };
  std::ostringstream out;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n5\n1 1 \"bottom\"\n"
         "1 2 \"right\"\n1 3 \"top\"\n1 4 \"left\"\n2 5 \"body\"\n$EndPhysicalNames\n"
         "$Entities\n0 4 1 0\n1 0 0 0 1 0 0 1 1 0\n2 1 0 0 1 1 0 1 2 0\n3 0 1 0 1 1 0 1 3 0\n"
         "4 0 0 0 0 1 0 1 4 0\n1 0 0 0 1 1 0 1 5 4 1 2 3 4\n$EndEntities\n";
  out << "$Nodes\n1 " << m * m << " 1 " << m * m << "\n2 1 0 " << m * m << "\n";
  for (int k = 1; k <= m * m; ++k) out << k << "\n";
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) out << double(i) / n << " " << double(j) / n << " 0\n";
  out << "$EndNodes\n$Elements\n5 " << 4 * n + 2 * n * n << " 1 " << 4 * n + 2 * n * n << "\n";
  int tag = 1;
  const std::array<std::function<std::pair<int, int>(int)>, 4> sides = {
      [&](int k) {
        return std::pair{node(k, 0), node(k + 1, 0)};
      },
      [&](int k) {
        return std::pair{node(n, k), node(n, k + 1)};
      },
      [&](int k) {
        return std::pair{node(n - k, n), node(n - k - 1, n)};
      },
      [&](int k) {
        return std::pair{node(0, n - k), node(0, n - k - 1)};
      }};
  for (int c = 0; c < 4; ++c) {
    out << "1 " << c + 1 << " 1 " << n << "\n";
    for (int k = 0; k < n; ++k) {
      const auto [a, b] = sides[c](k);
      out << tag++ << " " << a << " " << b << "\n";
    }
  }
  out << "2 1 2 " << 2 * n * n << "\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      out << tag++ << " " << node(i, j) << " " << node(i + 1, j) << " " << node(i + 1, j + 1)
          << "\n";
      out << tag++ << " " << node(i, j) << " " << node(i + 1, j + 1) << " " << node(i, j + 1)
          << "\n";
    }
  out << "$EndElements\n";
  return out.str();
}

/// The name of the k-th extra physical group of mesh_with_names.
inline std::string extra_group(int k) { return "g" + std::to_string(k); }

/// The smallest mesh of a dimension with `extra` more physical names of its boundary's
/// dimension (tags 100, 101, …, named extra_group(k)) that no element uses, so that each one is
/// a boundary group of the mesh. 2D: the unit square as two triangles, groups "bottom", "right",
/// "top", "left". 3D: one tetrahedron, groups "bottom" (on z = 0) and "rest".
inline std::string mesh_with_names(int dimension, int extra) {
  std::ostringstream out;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n";
  if (dimension == 2) {
    out << extra + 4 << "\n1 1 \"bottom\"\n1 2 \"right\"\n1 3 \"top\"\n1 4 \"left\"\n";
  } else {
    out << extra + 2 << "\n2 1 \"bottom\"\n2 2 \"rest\"\n";
  }
  for (int k = 0; k < extra; ++k)
    out << dimension - 1 << " " << 100 + k << " \"" << extra_group(k) << "\"\n";
  out << "$EndPhysicalNames\n";
  if (dimension == 2)
    out << "$Entities\n0 4 1 0\n1 0 0 0 1 0 0 1 1 0\n2 1 0 0 1 1 0 1 2 0\n3 0 1 0 1 1 0 1 3 0\n"
           "4 0 0 0 0 1 0 1 4 0\n1 0 0 0 1 1 0 0 4 1 2 3 4\n$EndEntities\n"
           "$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n"
           "$Elements\n5 6 1 6\n1 1 1 1\n1 1 2\n1 2 1 1\n2 2 3\n1 3 1 1\n3 3 4\n1 4 1 1\n4 4 1\n"
           "2 1 2 2\n5 1 2 3\n6 1 3 4\n$EndElements\n";
  else
    out << "$Entities\n0 0 2 1\n1 0 0 0 1 1 0 1 1 0\n2 0 0 0 1 1 1 1 2 0\n1 0 0 0 1 1 1 0 0\n"
           "$EndEntities\n"
           "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
           "$Elements\n3 5 1 5\n2 1 2 1\n1 1 2 3\n2 2 2 3\n2 1 2 4\n3 1 3 4\n4 2 3 4\n"
           "3 1 4 1\n5 1 2 3 4\n$EndElements\n";
  return out.str();
}

}  // namespace fosls::service::testing
