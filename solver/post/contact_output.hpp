#pragma once
// What users look at (docs/method.md §6): contact pressure per contact edge, gap, contact zone and
// resultant force, from a solution in the space's rotated, scaled coordinates.

#include <vector>

#include "assembly/fosls_assembler.hpp"

namespace fosls {

struct ContactEdgeResult {
  int edge = -1;
  double x = 0, y = 0;  ///< midpoint
  double s = 0;         ///< arc length along the contact boundary (chain order)
  double pressure = 0;  ///< p = −σ_nn (physical units), constant on the edge
  double gap = 0;       ///< remaining gap g − u·n, mean over the edge
  bool active = false;  ///< in contact: pressure > 0
};

struct ContactResult {
  std::vector<ContactEdgeResult> edges;  ///< ordered along the contact boundary
  double force_x = 0, force_y = 0;       ///< ∫_Γ_C σn ds: the obstacle's force on the body
};

ContactResult contact_output(const FoslsAssembler& assembler, const AssembledProblem& problem,
                             const Vector& x_full);

}  // namespace fosls
