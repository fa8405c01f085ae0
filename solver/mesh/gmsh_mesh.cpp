#include "mesh/gmsh_mesh.hpp"

#include <signal.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "mesh/coarse_mesh_estimate.hpp"
#include "mesh/geometry_checks.hpp"
#include "mesh/mesher_protocol.hpp"
#include "mesh/plane_geometry.hpp"
#include "mesh/tet_msh_reader.hpp"
#include "process/child_process.hpp"

namespace fosls {

namespace {

const std::string kGeometryField = "/geometry";
const std::string kGeoFileField = "/geo_file";
const std::string kSizeField = "/size";

/// The mesher program: FOSLS_MESHER when set, else beside this program, else in the build.
std::string mesher_program() { return sibling_program("fosls-mesher", "FOSLS_MESHER"); }

std::string seconds_text(std::chrono::milliseconds t) { return plane::num(t.count() / 1000.0); }

/// Every way the mesher can end, as a MeshError at `field` (or MeshingCancelled); returns
/// only on an answer that is JSON.
nlohmann::json answer_of(const ChildResult& r, const std::string& field,
                         const MesherLimits& limits) {
  const std::string change = "; use a larger mesh size or a simpler geometry";
  const std::string memory = "gmsh ran out of memory while meshing (the mesher may use " +
                             std::to_string(limits.memory_bytes >> 20) + " MiB)" + change;
  const std::string time =
      "gmsh did not finish meshing within " + seconds_text(limits.time) + " s" + change;
  switch (r.end) {
    case ChildResult::End::kCancelled:
      throw MeshingCancelled();
    case ChildResult::End::kTimedOut:
      throw MeshError(field, time);
    case ChildResult::End::kOutputTooLarge:
      throw MeshError(field, "the mesh is too large to be returned" + change);
    case ChildResult::End::kSignaled:
      if (r.ran_out_of_memory()) throw MeshError(field, memory);
      if (r.signal == SIGXCPU) throw MeshError(field, time);
      if (r.signal == SIGKILL)
        throw MeshError(field,
                        "the mesher was killed (signal 9), most likely by the system "
                        "running out of memory" +
                            change);
      throw MeshError(field, "gmsh crashed while meshing this geometry (" + r.describe() +
                                 "); this happens with degenerate geometry: parts much thinner "
                                 "than the mesh size, or nearly coincident points. Change the "
                                 "geometry or the mesh size");
    case ChildResult::End::kExited:
      break;
  }
  if (r.exit_code != 0) {
    if (r.ran_out_of_memory()) throw MeshError(field, memory);
    throw std::runtime_error("the mesher failed (" + r.describe() + "): " + r.errors);
  }
  try {
    return nlohmann::json::parse(r.output);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("the mesher's answer is not JSON: ") + e.what());
  }
}

/// Runs the mesher on `request` and reads its answer with `read` (read_answer or
/// read_msh_answer, whose std::invalid_argument means the mesher broke the protocol).
template <class Read>
auto run_mesher_process(const MeshRequest& request, const std::string& field,
                        const MeshingControl& control, Read read) {
  ChildOptions options;
  options.argv = {mesher_program()};
  options.input = request_to_json(request).dump();
  options.limits.wall = control.limits.time;
  options.limits.cpu_seconds = control.limits.time.count() / 1000.0 + 5;
  options.limits.address_space_bytes = control.limits.memory_bytes;
  options.cancel = control.cancel;
  const nlohmann::json answer = answer_of(run_child(options), field, control.limits);
  try {
    return read(answer);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
}

/// Checks what a .geo request needs before a process is started; returns the absolute path.
std::string checked_geo_file(const std::string& path, double size) {
  if (!(size > 0) || !std::isfinite(size))
    throw MeshError(kSizeField, "the mesh size must be a positive number");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || !std::ifstream(path).good())
    throw MeshError(kGeoFileField, "cannot read the .geo file '" + path +
                                       "': it does not exist or is not a readable file");
  return std::filesystem::absolute(path, ec).string();
}

/// Runs the mesher on `request` and builds the Mesh of its answer.
Mesh run_mesher(const MeshRequest& request, const std::string& field, const MeshingControl& control,
                const std::string& hint) {
  MeshData d = run_mesher_process(request, field, control,
                                  [](const nlohmann::json& j) { return read_answer(j); });
  try {
    return Mesh(std::move(d.vertices), std::move(d.triangles), std::move(d.segments),
                std::move(d.group_names), std::move(d.curves));
  } catch (const std::invalid_argument& e) {
    throw MeshError(field, std::string("the generated mesh is not valid: ") + e.what() + hint);
  }
}

}  // namespace

Mesh mesh_from_geometry(const GeometrySpec& geometry, double size, const MeshingControl& control) {
  SizeField field;
  field.size = size;
  return mesh_from_geometry(geometry, field, control);
}

Mesh mesh_from_geometry(const GeometrySpec& geometry, const SizeField& size,
                        const MeshingControl& control) {
  // Everything that needs no gmsh is checked here, before a process is started.
  std::vector<MeshProblem> problems = check_size_field(size);
  for (auto& p : validate_geometry(geometry)) problems.push_back(std::move(p));
  if (problems.empty()) problems = check_coarse_mesh_estimate(estimate_coarse_mesh(geometry, size));
  if (!problems.empty()) throw MeshError(std::move(problems));
  return run_mesher(GeometryMeshRequest{geometry, size}, kGeometryField, control, "");
}

Mesh mesh_from_geo_file(const std::string& path, double size, const MeshingControl& control) {
  return run_mesher(GeoFileMeshRequest{checked_geo_file(path, size), size}, kGeoFileField, control,
                    "; put every boundary curve of the .geo file in a Physical Curve and mesh "
                    "one plane surface in z = 0");
}

TetMesh tet_mesh_from_geo_file(const std::string& path, double size,
                               const MeshingControl& control) {
  const std::string text =
      run_mesher_process(GeoFile3dMeshRequest{checked_geo_file(path, size), size}, kGeoFileField,
                         control, [](const nlohmann::json& j) { return read_msh_answer(j); });
  try {
    return tet_mesh_from_msh(text);
  } catch (const MeshError& e) {
    // The text is gmsh's, not the user's: what is wrong is in the .geo file.
    std::vector<MeshProblem> problems = e.problems();
    for (MeshProblem& p : problems) {
      p.field = kGeoFileField;
      p.detail = "the mesh gmsh made from it is not usable: " + p.detail;
    }
    throw MeshError(std::move(problems));
  }
}

}  // namespace fosls
