#pragma once
// Meshing through the gmsh C++ API. gmsh keeps global state and is not thread-safe, so every
// gmsh call in the process goes through gmsh_mutex(); gmsh errors become CaseException.

#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "case/case_error.hpp"
#include "mesh/geometry_spec.hpp"
#include "mesh/mesh.hpp"

namespace fosls {

/// The one mutex that guards every gmsh call in the process. Hold it for the whole sequence of
/// calls that builds or reads a model: gmsh's current model is global.
std::mutex& gmsh_mutex();

/// Initialises gmsh once per process (no configuration files, no terminal output). The caller
/// must hold gmsh_mutex().
void ensure_gmsh_initialized();

/// Target edge length h(x, y) > 0 of a graded mesh.
using MeshSizeField = std::function<double(const Point&)>;

/// Estimated coarse triangles above which meshing is refused: a too small `size` would
/// otherwise let gmsh run for minutes and exhaust memory.
inline constexpr double kMaxCoarseTriangles = 250000;

/// Every problem of a declarative geometry, each with its pointer under /mesh/geometry:
/// indices out of range, non-finite coordinates, zero-length curves, arcs whose end points are
/// not equidistant from the centre (1e-9 relative) or that span half a circle, curves that
/// cross, touch or overlap other than at shared end points, curves that do not form exactly
/// one closed loop, curves in no group or in two, empty or repeated group names.
std::vector<CaseError> validate_geometry(const GeometrySpec& geometry);

/// Meshes a declarative geometry with the uniform target edge length `size`. Boundary groups
/// are the geometry's groups (same order); every edge on an arc carries a BoundaryCurve so that
/// refinement puts new midpoints on the circle. Throws CaseException listing every problem of
/// validate_geometry, a too small size (/mesh/size) or a gmsh failure (/mesh/geometry).
Mesh mesh_from_geometry(const GeometrySpec& geometry, double size);

/// As above with a graded target edge length h(x, y) (used by the shipped Hertz mesh).
Mesh mesh_from_geometry(const GeometrySpec& geometry, const MeshSizeField& size);

/// Meshes a gmsh .geo script (command line only: scripts can run shell commands). Physical
/// curves become boundary groups (named by their physical name, or by their number when
/// unnamed); circle arcs are recognised so refinement snaps onto them. `size` caps the edge
/// length (Mesh.MeshSizeMax); sizes set in the script still apply below it. Errors are
/// CaseException with pointer /mesh/geo_file.
Mesh mesh_from_geo_file(const std::string& path, double size);

}  // namespace fosls
