#pragma once
// Shipped geometries: the rectangle `square` and the Hertz half disk `hertz`.

#include "mesh/geometry_spec.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "mesh/mesh.hpp"

namespace fosls {

/// Rectangle [x0, x0 + width] × [y0, y0 + height] with boundary groups bottom, right, top, left.
struct SquareParams {
  double x0 = 0.0;
  double y0 = 0.0;
  double width = 1.0;
  double height = 1.0;
  /// Target edge length of the coarse mesh.
  double size = 0.25;
};
Mesh make_square(const SquareParams& p);

/// Lower half of the disk of radius R centred at (0, R): flat side up at y = R, touching the
/// plane y = 0 at the origin. Groups: `top` (flat side), `contact` (arc points with
/// |x| ≤ contact_fraction · R) and `free` (rest of the arc). The coarse mesh is graded towards
/// the contact point: edge length ≈ size near the origin growing to ≈ grading · size far away.
/// Meshed by gmsh in the mesher process (gmsh_mesh.hpp); throws std::invalid_argument for bad
/// parameters and MeshError when meshing fails.
struct HertzParams {
  double radius = 1.0;
  double contact_fraction = 0.5;
  double size = 0.1;
  double grading = 7.0;
};
Mesh make_hertz(const HertzParams& p, const MeshingControl& control = {});

/// An outline and the size field gmsh meshes it with.
struct GmshOutline {
  GeometrySpec geometry;
  SizeField size;
};

/// The outline make_hertz meshes, without meshing it; throws std::invalid_argument for bad
/// parameters.
GmshOutline hertz_outline(const HertzParams& p);

}  // namespace fosls
