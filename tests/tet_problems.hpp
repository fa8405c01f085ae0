#pragma once
// 3D problems shared by the 3D tests and fosls-bench-3d.
#include "assembly/tet_assembler.hpp"

namespace fosls::testing {

/// The 3D Signorini block: the unit cube pressed down by 0.05 at its top (Dirichlet) onto the
/// gap 0.4 ((x − ½)² + (y − ½)²) below its bottom (contact), traction-free sides; the groups of
/// make_box.
inline TetProblemData signorini_block(double lambda) {
  TetProblemData d;
  d.material = {.mu = 1.0, .lambda = lambda};
  d.groups.resize(6);  // left, right, front, back, bottom, top
  d.groups[4].role = GroupRole::kContact;
  d.groups[4].gap = [](const Point3& x) {
    return 0.4 * ((x.x() - 0.5) * (x.x() - 0.5) + (x.y() - 0.5) * (x.y() - 0.5));
  };
  d.groups[5].role = GroupRole::kDirichlet;
  d.groups[5].values[2] = [](const Point3&) { return -0.05; };
  return d;
}

}  // namespace fosls::testing
