#include "assembly/solution_prolongation.hpp"

#include <stdexcept>

#include "fem/transfer.hpp"

namespace fosls {

Vector prolongate_to_finest(const Discretization& disc, const Vector& full_coarse) {
  const int top = disc.num_levels() - 1;
  if (top < 1) throw std::invalid_argument("prolongate_to_finest: there is no coarser level");
  const FoslsSpace<2>& coarse = disc.space(top - 1);
  const FoslsSpace<2>& fine = disc.space(top);
  if (full_coarse.size() != coarse.num_dofs())
    throw std::invalid_argument("prolongate_to_finest: the vector is not of the coarser level");
  const RefinementMaps& maps = disc.meshes().maps[top];
  const SparseMatrix cartesian = cartesian_prolongation(coarse.mesh(), fine.mesh(), maps);
  // The multilevel transfer maps free DOFs to free DOFs: right for corrections, which vanish
  // on fixed DOFs, but a solution's fine free values also interpolate coarse fixed ones (a new
  // vertex between a Dirichlet vertex and a free one takes half the prescribed displacement).
  // Without that part the start of every adaptive step after the first had an energy excess
  // of 20–400 J (docs/performance.md, adaptivity).
  Vector x_free(coarse.num_free()), fixed = full_coarse;
  for (int f = 0; f < coarse.num_free(); ++f) {
    x_free[f] = full_coarse[coarse.free_to_full()[f]];
    fixed[coarse.free_to_full()[f]] = 0.0;
  }
  const Vector fixed_fine = fine.rotation().transpose() * (cartesian * (coarse.rotation() * fixed));
  Vector x = free_prolongation(coarse, fine, maps, cartesian) * x_free;
  for (int f = 0; f < fine.num_free(); ++f) x[f] += fixed_fine[fine.free_to_full()[f]];
  return x;
}

}  // namespace fosls
