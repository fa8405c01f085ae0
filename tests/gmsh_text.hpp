#pragma once
// MSH 4.1 ASCII text written by gmsh itself, in this process (test code only: the product runs
// gmsh in fosls-mesher), for the tests of the msh readers.
#include <gmsh.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "mesher/gmsh_session.hpp"

namespace fosls::testing {

/// The text of the model that `build` makes (with any meshing options it sets), meshed in
/// `dimension`; gmsh's element order is reset to 1 and the model cleared afterwards.
inline std::string gmsh_msh_text(int dimension, const std::function<void()>& build) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("fosls_gmsh_text_" + std::to_string(::getpid()) + ".msh");
  {
    std::lock_guard<std::mutex> lock(gmsh_mutex());
    ensure_gmsh_initialized();
    gmsh::clear();
    build();
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::model::mesh::generate(dimension);
    gmsh::write(path.string());
    gmsh::option::setNumber("Mesh.ElementOrder", 1);
    gmsh::clear();
  }
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  std::filesystem::remove(path);
  return s.str();
}

}  // namespace fosls::testing
