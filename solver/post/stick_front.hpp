#pragma once
// The stick zone with its fronts located within the edges that hold them. The edges whose
// vertices have not slipped in the step (ContactEdgeResult::State::kStick) end at the last
// vertex that did not slip; the front itself lies inside the next edge, whose far vertex slips.
// Near a stick–slip front where the traction reaches the slip bound continuously (Cattaneo–
// Mindlin, Spence) the slip grows like k d^(3/2) with the distance d beyond the front, so
// slip^(2/3) is locally linear in d: the front is where the line through the slip^(2/3) of the
// first two slipping vertices beyond the stick zone reaches zero, kept within the edge between
// the last sticking vertex and the first slipping one (docs/method.md §8.3, "Where the stick
// zone ends"). 2D only: friction is 2D only (§8.5). The 3D contact zone's front is located by
// the same idea (a power of the profile linear near the front) in post/contact_front.hpp.

#include <vector>

#include "post/contact_output.hpp"

namespace fosls {

/// The distance beyond the last sticking vertex at which the front lies, from the slips
/// `slip1`, `slip2` (absolute values) of the first two slipping vertices at distances d1 < d2
/// beyond it: the zero of the line through (d1, slip1^(2/3)) and (d2, slip2^(2/3)), within
/// [0, d1]. 0 (the whole-edge end) when the slip does not grow away from the front.
double stick_front_offset(double d1, double slip1, double d2, double slip2);

struct StickFronts {
  double start = 0, end = 0;  ///< arc length of the first and the last located front
  double width = 0;           ///< sum over the stick runs of the length between their fronts
};

/// The located fronts of the stick runs of `edges` (chain order, states and end slips set as
/// contact_output sets them). A run's end that meets an edge in state open or the end of the
/// boundary, or whose slipping edge beyond has no slipping neighbour in contact to fit with,
/// stays at the run's whole-edge end. All 0 without a stick edge.
StickFronts locate_stick_fronts(const std::vector<ContactEdgeResult>& edges);

}  // namespace fosls
