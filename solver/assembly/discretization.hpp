#pragma once
// A case's discrete problem on all levels: spaces, the assembled finest-level QP and the level
// hierarchy for the multilevel solvers.

#include <memory>
#include <vector>

#include "assembly/fosls_assembler.hpp"
#include "core/level_hierarchy.hpp"
#include "mesh/refinement.hpp"

namespace fosls {

class Discretization {
 public:
  /// Builds spaces on every level and assembles the finest one; throws TimeLimitReached once
  /// `deadline` has passed (polled between the levels' spaces and in the element loop).
  Discretization(MeshHierarchy meshes, ProblemData<2> data, const Deadline& deadline = {});

  int num_levels() const { return meshes_.num_levels(); }
  const MeshHierarchy& meshes() const { return meshes_; }
  const FoslsSpace<2>& space(int level) const { return *spaces_[level]; }
  const FoslsSpace<2>& finest_space() const { return *spaces_.back(); }
  const FoslsAssembler<2>& assembler() const { return *assembler_; }
  const AssembledProblem& problem() const { return problem_; }
  /// The problem for a frictional solve, which changes its bounds (Coulomb) and, while it
  /// runs, its kinked DOFs' b and bounds (solvers/kink_sides.hpp).
  AssembledProblem& mutable_problem() { return problem_; }
  const ProblemData<2>& data() const { return data_; }
  /// Builds the transfers, patches and contact links of the levels from
  /// coarsest_solver_level() up (not needed by pdas).
  LevelHierarchy build_level_hierarchy() const;

  /// The coarsest mesh level that the multilevel solvers use: the first whose contact edges on
  /// curves turn the boundary normal by at most `max_turn` radians. Where a coarse edge
  /// spans a large part of an arc, coarse and fine contact boundaries differ too much for the
  /// coarse functions to represent the tractions there (measured on a punch with rounded
  /// corners: docs/performance.md, "Measurements behind choices in the code").
  int coarsest_solver_level(double max_turn = kMaxCoarseTurn) const;
  static constexpr double kMaxCoarseTurn = 0.3;

 private:
  MeshHierarchy meshes_;
  ProblemData<2> data_;
  std::vector<std::unique_ptr<FoslsSpace<2>>> spaces_;
  std::unique_ptr<FoslsAssembler<2>> assembler_;
  AssembledProblem problem_;
};

/// Vertex patches of a space in its free numbering (docs/method.md §4.1), in the order of
/// two_vertex_blocks: two blocks a smoother may sweep at the same time, then the separator;
/// `split`, when given, receives the ends of the two blocks. Only the patches of the vertices
/// with `selected[v]` set when `selected` is not empty.
std::vector<std::vector<int>> vertex_patches(const FoslsSpace<2>& space,
                                             std::array<int, 2>* split = nullptr,
                                             const std::vector<char>& selected = {});

/// The vertices of a refined mesh that local smoothing visits: the new ones (midpoints) and
/// their neighbours. Under uniform refinement that is every vertex; under a bisection step,
/// the refined region and one layer around it.
std::vector<char> new_vertices_and_neighbours(const Mesh& fine, const RefinementMaps& maps);

/// Free DOFs of the triangles within `layers` layers of the contact boundary (the strip
/// smoother's block), sorted; empty without contact. Two layers make the iteration counts
/// level-independent on the square benchmark, one layer does not (docs/performance.md,
/// "Measurements behind choices in the code").
std::vector<int> contact_strip(const FoslsSpace<2>& space, int layers = 2);

}  // namespace fosls
