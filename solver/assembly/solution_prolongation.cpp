#include "assembly/solution_prolongation.hpp"

#include <stdexcept>

#include "fem/transfer.hpp"

namespace fosls {

namespace {

/// The full DOF vector of level `level` + 1 for the full vector `full_coarse` of `level`: free
/// values by the multilevel transfer, fixed ones (and the fixed part of the free ones)
/// interpolated from the coarse fixed values.
template <int dim>
Vector prolongate_one_level(const Discretization<dim>& disc, const Vector& full_coarse, int level) {
  const FoslsSpace<dim>& coarse = disc.space(level);
  const FoslsSpace<dim>& fine = disc.space(level + 1);
  const SimplexRefinementMaps<dim>& maps = disc.meshes().maps[level + 1];
  const SparseMatrix cartesian = cartesian_prolongation<dim>(coarse.mesh(), fine.mesh(), maps);
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
  Vector full = fine.rotation().transpose() * (cartesian * (coarse.rotation() * fixed));
  const Vector x = free_prolongation<dim>(coarse, fine, maps, cartesian) * x_free;
  for (int f = 0; f < fine.num_free(); ++f) full[fine.free_to_full()[f]] += x[f];
  return full;
}

}  // namespace

template <int dim>
Vector prolongate_to_finest(const Discretization<dim>& disc, const Vector& full_coarse,
                            int from_level) {
  const int top = disc.num_levels() - 1;
  if (from_level < 0) from_level = top - 1;
  if (top < 1 || from_level >= top)
    throw std::invalid_argument("prolongate_to_finest: there is no coarser level");
  if (full_coarse.size() != disc.space(from_level).num_dofs())
    throw std::invalid_argument("prolongate_to_finest: the vector is not of the coarser level");
  Vector full = full_coarse;
  for (int level = from_level; level < top; ++level) full = prolongate_one_level(disc, full, level);
  const FoslsSpace<dim>& fine = disc.finest_space();
  Vector x(fine.num_free());
  for (int f = 0; f < fine.num_free(); ++f) x[f] = full[fine.free_to_full()[f]];
  return x;
}

template Vector prolongate_to_finest<2>(const Discretization<2>&, const Vector&, int);
template Vector prolongate_to_finest<3>(const Discretization<3>&, const Vector&, int);

}  // namespace fosls
