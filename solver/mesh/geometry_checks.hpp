#pragma once
// Checks of a declarative geometry that need no mesher: pure geometry, cheap enough to run on
// every submission before anything is meshed.

#include <vector>

#include "mesh/geometry_spec.hpp"
#include "mesh/mesh_error.hpp"

namespace fosls {

/// Every problem of a declarative geometry, each with its field under /geometry: indices out
/// of range, non-finite coordinates, zero-length curves, arcs whose end points are not
/// equidistant from the centre (1e-9 relative) or that span half a circle, curves that cross,
/// touch or overlap other than at shared end points, curves that do not form exactly one
/// closed loop, curves in no group or in two, empty or repeated group names.
std::vector<MeshProblem> validate_geometry(const GeometrySpec& geometry);

/// The loop of a geometry that validate_geometry accepted, in walking order, as signed curve
/// tags (curve index + 1, negative when the curve is walked from its end to its start); empty
/// when the curves do not form one loop.
std::vector<int> walk_loop(const GeometrySpec& geometry);

}  // namespace fosls
