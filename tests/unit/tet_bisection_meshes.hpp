#pragma once
// Meshes for the tetrahedron bisection tests: a brick meshed by gmsh (unstructured, so the
// initial marking has all of Arnold–Mukherjee–Pouly's types).
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "mesh/gmsh_mesh.hpp"

namespace fosls {

inline TetMesh gmsh_brick(double size) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("fosls_tet_bisection_" + std::to_string(::getpid()) + ".geo");
  // A flat-sided brick (gmsh's surfaces are flat facets under refinement, so fine meshes nest).
  std::ofstream(path) << R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.8, 0.6};
Physical Surface("sides") = {1, 2, 3, 4};
Physical Surface("bottom") = {5};
Physical Surface("top") = {6};
)";
  TetMesh mesh = tet_mesh_from_geo_file(path.string(), size);
  std::filesystem::remove(path);
  return mesh;
}

}  // namespace fosls
