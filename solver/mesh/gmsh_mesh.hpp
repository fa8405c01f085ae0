#pragma once
// Meshing with gmsh, always in a child process (the program fosls-mesher): gmsh 4.8 can abort
// the whole process on degenerate input (an exception thrown inside an OpenMP region), loop
// for minutes or exhaust memory, and none of that may reach the caller. The geometry is
// checked here first (geometry_checks.hpp, coarse_mesh_estimate.hpp); then the mesher runs
// under a wall-clock deadline, a CPU limit and an address-space limit, and every way it can
// end becomes a Mesh or a MeshError whose field is relative to the mesh section.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "mesh/geometry_spec.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

/// Limits of one mesher process.
struct MesherLimits {
  std::chrono::milliseconds time{60000};            ///< wall clock (and, plus 5 s, CPU time)
  std::size_t memory_bytes = std::size_t{2} << 30;  ///< address space of the mesher
};

/// How a caller steers meshing.
struct MeshingControl {
  MesherLimits limits;
  /// When set and it becomes true, the mesher is killed and MeshingCancelled thrown.
  const std::atomic<bool>* cancel = nullptr;
};

/// Thrown when meshing stopped because MeshingControl::cancel was set.
class MeshingCancelled : public std::runtime_error {
 public:
  MeshingCancelled() : std::runtime_error("meshing was cancelled") {}
};

/// Meshes a declarative geometry with the uniform target edge length `size`. Boundary groups
/// are the geometry's groups (same order); every edge on an arc carries a BoundaryCurve so that
/// refinement puts new midpoints on the circle. Throws MeshError listing every problem of
/// validate_geometry, a too small size (/size), or a mesher failure, crash, timeout or lack
/// of memory (/geometry). Throws std::runtime_error only when the mesher cannot be run at all.
Mesh mesh_from_geometry(const GeometrySpec& geometry, double size,
                        const MeshingControl& control = {});

/// As above with a graded target edge length (used by the shipped Hertz mesh).
Mesh mesh_from_geometry(const GeometrySpec& geometry, const SizeField& size,
                        const MeshingControl& control = {});

/// Meshes a gmsh .geo script (command line only: scripts can run shell commands). Physical
/// curves become boundary groups (named by their physical name, or by their number when
/// unnamed); circle arcs are recognised so refinement snaps onto them. `size` caps the edge
/// length (Mesh.MeshSizeMax); sizes set in the script still apply below it. Errors are
/// MeshError at /geo_file or /size.
Mesh mesh_from_geo_file(const std::string& path, double size, const MeshingControl& control = {});

/// Meshes a gmsh .geo script in 3D (tetrahedra, 3D stage 1): physical surfaces become boundary
/// groups, the volumes are meshed (they need no physical group of their own), `size` caps the
/// edge length. Surfaces are flat facets under refinement (no SphereSurface). Errors as above,
/// at /geo_file or /size; a mesh gmsh made that the 3D reader refuses is reported at /geo_file.
TetMesh tet_mesh_from_geo_file(const std::string& path, double size,
                               const MeshingControl& control = {});

}  // namespace fosls
