#pragma once
// The contact width: the length of the contact zone along the boundary, with each contact front
// placed where the pressure profile reaches zero. The edges with p > 0 overestimate it: the
// front lies inside the outermost of them, and the discrete pressure has a small positive tail
// (docs/validation.md §1; docs/performance.md, "Measurements behind choices in the code").

#include "mesh/mesh.hpp"
#include "post/contact_output.hpp"

namespace fosls {

/// Sum over the runs of adjacent edges in contact of the distance along the boundary between
/// their two fronts. A front at the end of the contact boundary is that end. Elsewhere, near
/// the end x = a of a smooth contact the pressure behaves like c √(a − x) and an edge's
/// pressure is its mean: the front is the a for which the means of c √(a − x)₊ over the two
/// outermost loaded edges have their computed ratio (c cancels; the ratio is monotone in a;
/// sought from the outermost loaded edge's inner end to two edge lengths beyond its outer end,
/// by bisection). Where no such a exists (one loaded edge, or a pressure that does not fall
/// towards the front, as at a punch's corner) the front is the outer end of the outermost
/// loaded edge. 0 without contact.
double contact_width(const Mesh& mesh, const ContactResult& contact);

}  // namespace fosls
