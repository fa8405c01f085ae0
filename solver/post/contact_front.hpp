#pragma once
// The area of a 3D contact zone with its front located within the faces, not at their edges.
// The faces with p > 0 overestimate the zone, as 2D's edges do (contact_width.hpp): the front
// runs through the outermost of them, and each of those is counted whole. Near the front of a
// smooth contact the pressure behaves like c √d, d the distance inside the front, so p² is
// locally linear: each vertex of the contact boundary gets the value at the vertex of a
// least-squares plane through the p² of the loaded faces around it, and the zone is where the
// linear interpolant of those values is positive, within the loaded faces
// (docs/result-format.md, "3D results"; docs/validation.md §16).

#include <vector>

#include "mesh/tet_mesh.hpp"

namespace fosls {

/// A plane of symmetry of the problem: the fit at a vertex on it also sees the mirror images of
/// the faces around the vertex, which a model cut there does not hold.
struct MirrorPlane {
  Point3 point = Point3::Zero();
  Point3 normal = Point3::UnitX();  ///< unit
};

/// The area of the part of the faces `faces` (the contact boundary's) where p² interpolated from
/// its vertex values (above) is positive, counted only on faces with p > 0; `pressure` is
/// indexed by the mesh's faces. 0 without a loaded face. Never more than their area.
double area_within_front(const TetMesh& mesh, const std::vector<int>& faces,
                         const std::vector<double>& pressure,
                         const std::vector<MirrorPlane>& mirrors = {});

}  // namespace fosls
