#pragma once
// What the multilevel solvers know about the levels: sizes, transfers, vertex patches and how
// contact DOFs of neighbouring levels are related. Free DOF numbering, rotated coordinates.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

/// Another link of the same coarse contact facet (3D's quarters, or a facet with more than two
/// fine children): factor[k][i] = n_k · n_i from this link's child k to that link's child i.
struct LinkPartner {
  int link = -1;
  std::array<std::array<double, 2>, 2> factor = {{{0.0, 0.0}, {0.0, 0.0}}};
};

/// How the contact DOFs of a coarse level relate to those of a finer one, as DOF indices of the
/// two levels (-1 where the DOF is fixed). Used to carry the defect obstacle to the coarse level
/// by the non-linear projections of docs/method.md §4.3.
///
/// U_n: a fine contact vertex m (fine_un_mid) that is the P1 combination of coarse contact
/// vertices a, b and, inside a coarse face, c with the weights un_weight (½, ½ for the midpoint of
/// a coarse edge E = (a, b); a chain of midpoints along E, or across skipped levels a vertex
/// inside a coarse face, has other dyadic weights); m is −1 where E was kept.
/// S_n: the coarse S_n of a contact facet and up to two of its fine children (the halves of E).
struct ContactLink {
  int coarse_un_a = -1, coarse_un_b = -1, coarse_un_c = -1;  ///< coarse U_n at a, b, c
  int fine_un_a = -1, fine_un_mid = -1, fine_un_b = -1, fine_un_c = -1;
  std::array<double, 3> un_weight = {0.5, 0.5, 0.0};  ///< m's P1 weights of a, b, c
  int coarse_sn = -1;                                 ///< coarse S_n of E
  std::array<int, 2> fine_sn = {-1, -1};              ///< fine S_n of the two halves
  std::array<double, 2> sn_weight = {0.5, 0.5};       ///< P entry fine S_n ← coarse S_n
  /// flux_moves[k]: a fine field that takes one unit of normal flux off half k and puts it on
  /// the other half, divergence-free inside E's coarse triangle (it crosses the fine triangles
  /// between the two halves): first the other half's S_n, then the interior σ DOFs on the way.
  /// When only half k is truncated, the coarse S_n function moves half k's flux this way
  /// (TruncatedHierarchy::truncate_level), so that it keeps a bounded divergence. A link of one
  /// child among partners has flux_moves[0] only, towards its first partner's first child.
  std::array<std::vector<std::pair<int, double>>, 2> flux_moves;
  /// The other links of the same coarse facet, in order (empty where the facet has one link:
  /// always in 2D unless levels were skipped). When both children here are truncated, their
  /// share moves onto the first free child of a partner, along flux_moves[0]'s path.
  std::vector<LinkPartner> partners;
};

/// How an exact block solver factorises the block restricted to a free set
/// (solvers/free_set_solver.hpp): anew per free set, or once ordered with held rows.
enum class BlockFactorization { reduced, held_rows };

struct Level {
  int num_dofs = 0;
  /// P_j : level j−1 → level j (empty on the coarsest level).
  SparseMatrix prolongation;
  /// DOFs of each vertex patch: the vertex's u DOFs and both σ rows on every edge through it.
  std::vector<std::vector<int>> patches;
  /// Patches [0, patch_split[0]) and [patch_split[0], patch_split[1]) share no entry of x or
  /// of the residual: a sweep may run them on two threads, then the rest (the separator).
  std::array<int, 2> patch_split = {0, 0};
  /// Relation of the contact DOFs of level j−1 to those of level j.
  std::vector<ContactLink> links;
  /// DOFs of the triangles touching the contact boundary: the block of the strip smoother.
  std::vector<int> contact_strip;
  /// How the level's exact block solvers factorise: its strip smoother's and, on the coarsest
  /// level, the coarse solve's. 2D's strips and coarse meshes are thin or small and keep
  /// `reduced`; 3D's strips are slabs and its coarse meshes ordinary 3D sparse matrices
  /// (assembly/discretization.hpp, Discretization::kBlockFactorization).
  BlockFactorization block_factorization = BlockFactorization::reduced;
};

/// Levels coarsest first; the finest level is the one of the BoxQp.
struct LevelHierarchy {
  std::vector<Level> levels;
  int num_levels() const { return static_cast<int>(levels.size()); }
};

/// Empty when the hierarchy fits a problem of `finest_size` unknowns: P_j maps level j−1 to
/// level j, and every patch, strip and link index lies inside its level; otherwise what is
/// wrong (checked by FOSLS_ASSERT when a multilevel cycle is built).
std::string hierarchy_inconsistency(const LevelHierarchy& hierarchy, int finest_size);

}  // namespace fosls
