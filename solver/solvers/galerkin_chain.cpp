#include "solvers/galerkin_chain.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>

#include "solvers/cholmod_checks.hpp"
#include "solvers/galerkin_product.hpp"

namespace fosls {

GalerkinChain galerkin_chain(const SparseMatrix& A, const LevelHierarchy& hierarchy, int levels) {
  const int top = hierarchy.num_levels() - 1;
  GalerkinChain c;
  c.matrices.resize(std::max(top, 0));
  for (int j = top; j >= 1 && top - j < levels; --j) {
    SparseMatrix coarse =
        galerkin_product(j == top ? A : c.matrices[j], hierarchy.levels[j].prolongation);
    c.matrices[j - 1].swap(coarse);  // no move in Eigen 3.4: swapped, not copied
  }
  return c;
}

bool chain_is_definite(const SparseMatrix& A, const GalerkinChain& chain, int max_dofs) {
  const SparseMatrix* checked = chain.matrices.empty() ? &A : &chain.matrices[0];
  for (const SparseMatrix& m : chain.matrices)
    if (m.rows() <= max_dofs) checked = &m;
  if (A.rows() <= max_dofs) checked = &A;
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt;
  return compute_checked(llt, *checked);
}

}  // namespace fosls
