#pragma once
// Coulomb friction on a coarser level of the nested iteration (docs/method.md §8.4): the
// frictional edges and kinks of the Galerkin problem of level j−1, found from those of level j
// through the prolongation, so that the coarse levels can solve Coulomb's problem and hand the
// fine level a start near its contact zone, slip bounds and stick/slip states.
//
// A coarse contact edge E has two fine halves; its S_t is the coarse DOF carrying most of each
// half's S_t (a fine S_t is half its coarse edge's), its S_n likewise, and its kinks are the
// U_t of its end points, the coarse DOFs carrying most of the fine U_t at the halves' outer
// end points (the fine U_t at E's midpoint, shared by both halves, is the average of the two
// and has no coarse kink). With these the coarse problem is the coarse mesh's own discretisation
// of the friction term: Galerkin's bilinear coupling C3 Σ S_t (ΔU_t,p + ΔU_t,q)/2 of the halves
// is the coarse edge's, the bound 𝔣 max(0, −S_n,E) bounds the sum of the halves' tractions.

#include <optional>
#include <vector>

#include "core/box_qp.hpp"
#include "core/friction_law.hpp"
#include "core/kinks.hpp"

namespace fosls {

struct CoarseFriction {
  FrictionLayout layout;
  Kinks kinks;  ///< weights 0 (Coulomb's start, s̄ = 0); set by the solve's updates
  /// The coarse S_t and kinked U_t: the coarse problem's row obstacles (BoxQp::row_obstacles).
  std::vector<int> row_obstacles;
};

/// For each row of P, the column of its entry of largest magnitude (-1 for an empty row).
std::vector<int> main_columns(const SparseMatrix& P);

/// The friction of level j−1 from that of level j (`fine`, `fine_kinks`) and P_j; nullopt when
/// the fine edges do not pair up as halves of coarse edges with a free U_t at their common
/// midpoint (then the nested iteration solves the coarser levels without friction, as it does
/// for Tresca).
std::optional<CoarseFriction> coarser_friction(const FrictionLayout& fine, const Kinks& fine_kinks,
                                               const SparseMatrix& P);

}  // namespace fosls
