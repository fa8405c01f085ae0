#include "post/contact_force.hpp"

#include "fem/contact_frame.hpp"

namespace fosls {

template <int dim>
std::vector<double> contact_pressure(const FoslsSpace<dim>& space, const Vector& x_full,
                                     double stress_scale) {
  std::vector<double> p(space.mesh().num_facets(), 0.0);
  for (int f = 0; f < space.mesh().num_facets(); ++f)
    if (space.is_contact_facet(f)) p[f] = facet_pressure(space, x_full, stress_scale, f);
  return p;
}

template <int dim>
Vec<dim> contact_force(const FoslsSpace<dim>& space, const Vector& x_full, double stress_scale) {
  Vec<dim> force = Vec<dim>::Zero();
  for (int f = 0; f < space.mesh().num_facets(); ++f)
    if (space.is_contact_facet(f))
      force += normal_frame<dim>(space.mesh().facet_normal(f)) *
               x_full.segment<dim>(space.sigma_dof(f, 0));
  return stress_scale * force;
}

template std::vector<double> contact_pressure<2>(const FoslsSpace<2>&, const Vector&, double);
template std::vector<double> contact_pressure<3>(const FoslsSpace<3>&, const Vector&, double);
template Point contact_force<2>(const FoslsSpace<2>&, const Vector&, double);
template Point3 contact_force<3>(const FoslsSpace<3>&, const Vector&, double);

}  // namespace fosls
