#pragma once
// The coarse obstacles of the monotone multilevel method (docs/method.md §4.3): the bounds of a
// coarse correction that keep every prolongated correction below the finer level's obstacle.

#include <array>
#include <vector>

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"

namespace fosls {

/// How the obstacle of the normal displacement is carried to a coarse contact edge
/// (docs/method.md §4.3): (a) least restrictive, (b) min of end and midpoint, (c) min over the
/// edge.
enum class CoarseProjection { kA, kB, kC };

/// From the defects d ≥ 0 of the bounded DOFs of level j (kNoBound where a DOF is unbounded or
/// truncated) to upper bounds of level j−1 that keep every prolongated coarse correction below
/// d (exactly where contact normals agree between the levels). `coarse_hi` must be initialised
/// (e.g. to kNoBound); it is only lowered. `sn_weights`, when given, replaces the links'
/// prolongation weights of the fine S_n (one pair per link): the truncated prolongation moves
/// flux between the halves of a coarse edge.
void project_defect(const Level& fine_level, CoarseProjection projection, const Vector& defect,
                    Vector& coarse_hi,
                    const std::vector<std::array<double, 2>>* sn_weights = nullptr);

}  // namespace fosls
