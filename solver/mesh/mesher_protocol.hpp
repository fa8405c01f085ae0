#pragma once
// What the parent and the mesher process (fosls-mesher) say to each other: a request on the
// mesher's stdin, one JSON document on its stdout with the mesh or the problems. Doubles are
// written in the shortest form that reads back to the same bits, so a mesh made in the child
// is exactly the mesh the parent gets.

#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "mesh/geometry_spec.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_error.hpp"

namespace fosls {

/// Mesh a declarative geometry with a size field.
struct GeometryMeshRequest {
  GeometrySpec geometry;
  SizeField size;
};

/// Mesh a gmsh .geo script (command line only), edge length capped at `size`.
struct GeoFileMeshRequest {
  std::string path;
  double size = 0;
};

/// Mesh a gmsh .geo script in 3D (tetrahedra), edge length capped at `size`; the answer is the
/// mesh as MSH 4.1 text, read by tet_msh_reader.hpp.
struct GeoFile3dMeshRequest {
  std::string path;
  double size = 0;
};

using MeshRequest = std::variant<GeometryMeshRequest, GeoFileMeshRequest, GeoFile3dMeshRequest>;

/// The arrays a Mesh is built from, as the mesher produced them.
struct MeshData {
  std::vector<Point> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<BoundarySegment> segments;
  std::vector<std::string> group_names;
  std::vector<BoundaryCurve> curves;
};

nlohmann::json request_to_json(const MeshRequest& request);
/// Throws std::invalid_argument when the text is not a request.
MeshRequest request_from_json(const nlohmann::json& j);

/// The mesher's answer: a mesh, or the problems that stopped it.
nlohmann::json mesh_answer(const MeshData& mesh);
nlohmann::json problems_answer(const std::vector<MeshProblem>& problems);

/// Reads an answer: the mesh, or throws MeshError with the mesher's problems. Throws
/// std::invalid_argument when the text is not an answer.
MeshData read_answer(const nlohmann::json& j);

/// A 3D answer: the tetrahedral mesh as MSH 4.1 text.
nlohmann::json msh_answer(const std::string& msh_text);
/// Reads a 3D answer as read_answer does a 2D one.
std::string read_msh_answer(const nlohmann::json& j);

}  // namespace fosls
