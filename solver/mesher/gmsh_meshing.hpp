#pragma once
// The calls into gmsh that turn a mesh request into mesh arrays, in this process. Meant for
// the mesher program only (see gmsh_session.hpp).

#include "mesh/mesher_protocol.hpp"

namespace fosls {

/// Meshes a declarative geometry: validates it (geometry_checks.hpp) and the estimated size
/// (coarse_mesh_estimate.hpp) first; boundary groups are the geometry's groups (same order);
/// every edge on an arc carries a BoundaryCurve so that refinement puts new midpoints on the
/// circle. Throws MeshError with fields under /geometry and /size.
MeshData mesh_geometry_with_gmsh(const GeometryMeshRequest& request);

/// Meshes a gmsh .geo script. Physical curves become boundary groups (named by their physical
/// name, or by their number when unnamed); circle arcs are recognised so refinement snaps onto
/// them. `size` caps the edge length (Mesh.MeshSizeMax); sizes set in the script still apply
/// below it. The caller has checked the size and that the file is readable. Throws MeshError
/// at /geo_file or /size.
MeshData mesh_geo_file_with_gmsh(const GeoFileMeshRequest& request);

/// Meshes a gmsh .geo script in 3D: tetrahedra with `size` capping the edge length, physical
/// surfaces as the boundary groups (all volumes made one physical volume when the script has
/// none). Returns the mesh as MSH 4.1 ASCII text. Throws MeshError at /geo_file or /size.
std::string mesh_geo_file_3d_with_gmsh(const GeoFile3dMeshRequest& request);

}  // namespace fosls
