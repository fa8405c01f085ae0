#include "assembly/solution_prolongation.hpp"

#include <stdexcept>

#include "fem/transfer.hpp"

namespace fosls {

Vector prolongate_to_finest(const Discretization& disc, const Vector& x_coarse) {
  const int top = disc.num_levels() - 1;
  if (top < 1) throw std::invalid_argument("prolongate_to_finest: there is no coarser level");
  const FoslsSpace& coarse = disc.space(top - 1);
  const FoslsSpace& fine = disc.space(top);
  if (x_coarse.size() != coarse.num_free())
    throw std::invalid_argument("prolongate_to_finest: the vector is not of the coarser level");
  const RefinementMaps& maps = disc.meshes().maps[top];
  const SparseMatrix p = free_prolongation(
      coarse, fine, maps, cartesian_prolongation(coarse.mesh(), fine.mesh(), maps));
  return p * x_coarse;
}

}  // namespace fosls
