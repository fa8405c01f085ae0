#include "post/stick_front.hpp"

#include <algorithm>
#include <cmath>

namespace fosls {

namespace {

using State = ContactEdgeResult::State;

/// Edge `next` follows edge `edge` along the boundary (they share the vertex between them).
bool follows(const ContactEdgeResult& edge, const ContactEdgeResult& next) {
  return edge.ends[1] == next.ends[0];
}

/// The front beyond the end `side` (0: start, 1: end) of the stick run ending at edge `last`,
/// as a distance beyond the run's last vertex. `step` is −1 towards the start of the boundary
/// and +1 towards its end.
double front_beyond(const std::vector<ContactEdgeResult>& edges, int last, int step) {
  const int n = static_cast<int>(edges.size());
  const int side = step > 0 ? 1 : 0;  // the end of each edge that lies away from the run
  auto neighbour = [&](int k) {       // the edge beyond edge k, or −1
    const int m = k + step;
    if (m < 0 || m >= n) return -1;
    const bool joined = step > 0 ? follows(edges[k], edges[m]) : follows(edges[m], edges[k]);
    return joined && edges[m].state == State::kSlip ? m : -1;
  };
  const int first = neighbour(last);
  if (first < 0) return 0.0;
  const int second = neighbour(first);
  if (second < 0) return 0.0;
  const double d1 = edges[first].length, d2 = d1 + edges[second].length;
  return stick_front_offset(d1, std::abs(edges[first].end_slip[side]), d2,
                            std::abs(edges[second].end_slip[side]));
}

}  // namespace

double stick_front_offset(double d1, double slip1, double d2, double slip2) {
  const double r1 = std::pow(slip1, 2.0 / 3.0), r2 = std::pow(slip2, 2.0 / 3.0);
  if (!(r2 > r1)) return 0.0;
  return std::clamp(d1 - r1 * (d2 - d1) / (r2 - r1), 0.0, d1);
}

StickFronts locate_stick_fronts(const std::vector<ContactEdgeResult>& edges) {
  StickFronts fronts;
  const int n = static_cast<int>(edges.size());
  bool found = false;
  for (int i = 0; i < n;) {
    if (edges[i].state != State::kStick) {
      ++i;
      continue;
    }
    int j = i;  // the stick run is [i, j]
    while (j + 1 < n && edges[j + 1].state == State::kStick && follows(edges[j], edges[j + 1])) ++j;
    const double start = edges[i].s - 0.5 * edges[i].length - front_beyond(edges, i, -1);
    const double end = edges[j].s + 0.5 * edges[j].length + front_beyond(edges, j, +1);
    if (!found) fronts.start = start;
    found = true;
    fronts.end = end;
    fronts.width += end - start;
    i = j + 1;
  }
  return fronts;
}

}  // namespace fosls
