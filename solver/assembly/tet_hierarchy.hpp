#pragma once
// The 3D levels for the multilevel solvers (docs/method.md §11): transfers between the spaces
// of a tetrahedral hierarchy and the vertex patches, as a LevelHierarchy — the solvers
// themselves are the 2D ones, which see matrices, patches and transfers only.

#include <memory>
#include <vector>

#include "assembly/fosls_assembler.hpp"
#include "core/level_hierarchy.hpp"
#include "mesh/tet_refinement.hpp"

namespace fosls {

/// P_j between full Cartesian DOF vectors: u by P1 interpolation; σ: a fine face inside a
/// coarse face carries a quarter of its flux (with the sign of the two normals' agreement), a
/// fine face inside a coarse tetrahedron the exact flux of the coarse (linear) RT0 field.
Eigen::SparseMatrix<double> tet_prolongation(const TetMesh& coarse, const TetMesh& fine,
                                             const TetRefinementMaps& maps);

/// The vertex patches of a space in its free numbering: the vertex's u DOFs and the σ DOFs of
/// every face through it (the Arnold–Falk–Winther star), in two_vertex_blocks' order; `split`,
/// when given, receives the ends of the two blocks a sweep may run on two threads.
std::vector<std::vector<int>> tet_vertex_patches(const FoslsSpace<3>& space,
                                                 std::array<int, 2>* split = nullptr);

/// A case's 3D discretisation on all levels: spaces, the finest level's QP and the hierarchy.
class TetDiscretization {
 public:
  TetDiscretization(TetHierarchy meshes, ProblemData<3> data);
  TetDiscretization(const TetDiscretization&) = delete;  // the assembler refers to data_
  TetDiscretization& operator=(const TetDiscretization&) = delete;
  const TetHierarchy& meshes() const { return meshes_; }
  const FoslsSpace<3>& finest_space() const { return *spaces_.back(); }
  const FoslsAssembler<3>& assembler() const { return *assembler_; }
  const AssembledProblem& problem() const { return problem_; }
  LevelHierarchy build_level_hierarchy() const;

 private:
  TetHierarchy meshes_;
  ProblemData<3> data_;
  std::vector<std::unique_ptr<FoslsSpace<3>>> spaces_;
  std::unique_ptr<FoslsAssembler<3>> assembler_;
  AssembledProblem problem_;
};

}  // namespace fosls
