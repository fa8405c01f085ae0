#pragma once
// The smoothers a case can choose (`solver.smoother`): one row each, from which the multilevel
// cycle and pgs construct them and the case layer takes their names
// (case/format/solver_methods.hpp). A new smoother: its own files (a Smoother and its make_
// function) and an enumerator, a declaration and a row here (docs/architecture.md, "Where to add").

#include <memory>
#include <stdexcept>

#include "core/level_hierarchy.hpp"
#include "solvers/smoother.hpp"

namespace fosls {

enum class SmootherType { kPatch, kPoint };

/// The smoother of a level: on its matrix A (which must outlive it) and its patches.
using MakeSmoother = std::unique_ptr<Smoother> (*)(const SparseMatrix& A, const Level& level);

std::unique_ptr<Smoother> make_patch_smoother(const SparseMatrix& A, const Level& level);
std::unique_ptr<Smoother> make_point_smoother(const SparseMatrix& A, const Level& level);

struct SmootherInfo {
  SmootherType type;
  const char* name;     ///< the case's `solver.smoother`
  const char* summary;  ///< one line for docs and help
  MakeSmoother make;
};

inline constexpr SmootherInfo kSmootherTable[] = {
    {SmootherType::kPatch, "patch", "vertex-patch block smoother (robust in H(div))",
     make_patch_smoother},
    {SmootherType::kPoint, "point", "pointwise projected Gauss-Seidel", make_point_smoother},
};

inline const SmootherInfo& smoother_info(SmootherType type) {
  for (const SmootherInfo& s : kSmootherTable)
    if (s.type == type) return s;
  throw std::logic_error("a SmootherType is missing from kSmootherTable (smoother_table.hpp)");
}

}  // namespace fosls
