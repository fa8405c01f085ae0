// fosls-mesher: meshes one request with gmsh, in a process of its own, so that gmsh aborting
// (it can throw inside an OpenMP region on degenerate geometry, which ends the process) or
// running out of time or memory never takes the caller with it. Started by
// mesh/gmsh_mesh.cpp; not meant to be run by hand.
//
// Protocol (mesh/mesher_protocol.hpp): the request as JSON on stdin; on stdout one JSON
// document, {"mesh": ...} or {"problems": [...]}, and exit code 0. Exit code 2: the request
// was unreadable; 3: out of memory (also said on stderr). Anything gmsh prints goes to stderr.

#include <cerrno>
#include <iostream>
#include <iterator>
#include <new>
#include <string>

#include "mesh/mesher_protocol.hpp"
#include "mesher/gmsh_meshing.hpp"
#include "process/child_process.hpp"

int main() {
  using namespace fosls;
  die_with_parent();
  // Nothing a library prints can corrupt the answer: fd 1 now writes to stderr.
  const int answer_fd = fosls::take_stdout_for_answer();
  try {
    const std::string text{std::istreambuf_iterator<char>(std::cin),
                           std::istreambuf_iterator<char>()};
    MeshRequest request;
    try {
      request = request_from_json(nlohmann::json::parse(text));
    } catch (const std::exception& e) {
      std::cerr << "fosls-mesher: unreadable request: " << e.what() << '\n';
      return 2;
    }
    nlohmann::json answer;
    try {
      if (const auto* g = std::get_if<GeometryMeshRequest>(&request))
        answer = mesh_answer(mesh_geometry_with_gmsh(*g));
      else if (const auto* f = std::get_if<GeoFileMeshRequest>(&request))
        answer = mesh_answer(mesh_geo_file_with_gmsh(*f));
      else
        answer = msh_answer(mesh_geo_file_3d_with_gmsh(std::get<GeoFile3dMeshRequest>(request)));
    } catch (const MeshError& e) {
      answer = problems_answer(e.problems());
    }
    return fosls::write_all(answer_fd, answer.dump()) ? 0 : 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "fosls-mesher: out of memory (std::bad_alloc)\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "fosls-mesher: " << e.what() << '\n';
    return 1;
  }
}
