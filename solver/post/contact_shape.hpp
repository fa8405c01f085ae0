#pragma once
// The shape of the contact boundary: a straight line, one circular arc, or neither. An analytic
// comparison is offered by this, not by a case's name: Hertz applies to an arc against a plane.

#include "mesh/mesh.hpp"
#include "post/contact_output.hpp"

namespace fosls {

struct ContactShape {
  enum class Kind { kNone, kLine, kArc, kOther };
  Kind kind = Kind::kNone;       ///< kNone: no contact edges
  Point center = Point::Zero();  ///< kArc
  double radius = 0.0;           ///< kArc
};

/// Fits the vertices of the contact edges: a line when they are collinear, an arc when they
/// lie on one circle, each to 1e-6 of the boundary's extent (vertices on a curved boundary
/// lie on it exactly: refinement snaps midpoints onto arcs; a mesh read from MSH text is
/// exact to the digits written).
ContactShape contact_shape(const Mesh& mesh, const ContactResult& contact);

}  // namespace fosls
