#pragma once
// A case's discrete problem on all levels, in 2D and 3D: spaces, the assembled finest-level QP
// and the level hierarchy for the multilevel solvers.

#include <memory>
#include <vector>

#include "assembly/fosls_assembler.hpp"
#include "assembly/solver_levels.hpp"
#include "core/level_hierarchy.hpp"

namespace fosls {

template <int dim>
class Discretization {
 public:
  /// Layers of cells in the contact strip's block (contact_strip.hpp): two in 2D, one in 3D.
  static constexpr int kStripLayers = dim == 2 ? 2 : 1;
  /// How the exact block solvers factorise (core/level_hierarchy.hpp): 2D's strips and coarse
  /// meshes are thin or small and keep the reduced factorisation of the free block; 3D's strips
  /// are slabs and its coarse meshes ordinary 3D sparse matrices, factorised once with held
  /// rows (solvers/free_set_solver.hpp).
  static constexpr BlockFactorization kBlockFactorization =
      dim == 2 ? BlockFactorization::reduced : BlockFactorization::held_rows;

  /// Builds spaces on every level and assembles the finest one; throws TimeLimitReached once
  /// `deadline` has passed (polled between the levels' spaces and in the element loop).
  Discretization(SimplexHierarchy<dim> meshes, ProblemData<dim> data,
                 const Deadline& deadline = {});
  Discretization(const Discretization&) = delete;  // the spaces refer to meshes_
  Discretization& operator=(const Discretization&) = delete;
  Discretization(Discretization&&) = default;

  int num_levels() const { return meshes_.num_levels(); }
  const SimplexHierarchy<dim>& meshes() const { return meshes_; }
  const FoslsSpace<dim>& space(int level) const { return *spaces_[level]; }
  const FoslsSpace<dim>& finest_space() const { return *spaces_.back(); }
  const FoslsAssembler<dim>& assembler() const { return *assembler_; }
  const AssembledProblem& problem() const { return problem_; }
  /// The problem for a frictional solve, which changes its bounds (Coulomb) and, while it
  /// runs, its kinked DOFs' b and bounds (solvers/kink_sides.hpp).
  AssembledProblem& mutable_problem() { return problem_; }
  const ProblemData<dim>& data() const { return *data_; }
  /// Builds the transfers, patches, contact strips and contact links of the levels from
  /// coarsest_solver_level() up (not needed by pdas): of the levels that skip_close_levels keeps
  /// with `max_share` (assembly/solver_levels.hpp; every level of a uniform hierarchy).
  LevelHierarchy build_level_hierarchy(double max_share = kMaxSolverLevelShare) const;

  /// The coarsest mesh level that the multilevel solvers use: in 2D the first whose contact
  /// edges on arcs turn the boundary normal by at most `max_turn` radians. Where a coarse edge
  /// spans a large part of an arc, coarse and fine contact boundaries differ too much for the
  /// coarse functions to represent the tractions there (measured on a punch with rounded
  /// corners: docs/performance.md, "Measurements behind choices in the code"). 3D uses every
  /// level (its curved contact faces' turn is not limited: docs/method.md §11).
  int coarsest_solver_level(double max_turn = kMaxCoarseTurn) const;
  static constexpr double kMaxCoarseTurn = 0.3;

  /// The transfer between the free DOFs of mesh levels coarse < fine: the product of the
  /// levels' transfers between them (fem/transfer.hpp, free_prolongation).
  SparseMatrix free_transfer(int coarse, int fine) const;

 private:
  SimplexHierarchy<dim> meshes_;
  std::unique_ptr<ProblemData<dim>> data_;  ///< on the heap: the assembler refers to it
  std::vector<std::unique_ptr<FoslsSpace<dim>>> spaces_;
  std::unique_ptr<FoslsAssembler<dim>> assembler_;
  AssembledProblem problem_;
};

extern template class Discretization<2>;
extern template class Discretization<3>;

}  // namespace fosls
