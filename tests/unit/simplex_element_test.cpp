// The simplex element in both dimensions (fem/simplex_element.hpp): RT0's flux through its own
// facet is 1 and 0 through the others, its divergence is what the divergence theorem gives, P1
// is a partition of unity with the Kronecker property, and the quadrature integrates every
// product of two P1 functions exactly.
#include <gtest/gtest.h>

#include "fem/simplex_element.hpp"
#include "mesh/tet_refinement.hpp"
#include "perturbed_square.hpp"

namespace fosls {
namespace {

template <int dim>
SimplexMesh<dim> test_mesh() {
  if constexpr (dim == 2)
    return testing::perturbed_square(0.25);
  else
    return refine_tets_uniformly(make_box({2, 1, 2}, Point3(1.0, 0.7, 1.3))).fine;
}

template <class Dim>
class SimplexElementTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(SimplexElementTest, Dimensions);

TYPED_TEST(SimplexElementTest, Rt0FluxIsOneThroughItsFacetAndZeroThroughTheOthers) {
  constexpr int dim = TypeParam::value;
  const SimplexMesh<dim> mesh = test_mesh<dim>();
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SimplexElement<dim> e(mesh, t);
    for (int k = 0; k <= dim; ++k) {
      double outward_flux = 0.0;  // ∫_∂T ψ_k·n_T = ∫_T div ψ_k
      for (int j = 0; j <= dim; ++j) {
        const int f = mesh.cell_facet(t, j);
        // ψ_k is linear and the facet flat: the flux is the centroid value times |f| n_f.
        const double flux =
            e.rt0(k, mesh.facet_centroid(f)).dot(mesh.facet_normal(f)) * mesh.facet_measure(f);
        EXPECT_NEAR(flux, k == j ? 1.0 : 0.0, 1e-12) << "cell " << t << " k " << k;
        outward_flux += mesh.cell_facet_sign(t, j) * flux;
      }
      EXPECT_NEAR(e.rt0_div(k) * e.measure, outward_flux, 1e-12);
    }
  }
}

TYPED_TEST(SimplexElementTest, P1IsAPartitionOfUnityWithTheKroneckerProperty) {
  constexpr int dim = TypeParam::value;
  const SimplexMesh<dim> mesh = test_mesh<dim>();
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SimplexElement<dim> e(mesh, t);
    Vec<dim> sum = Vec<dim>::Zero();
    for (int k = 0; k <= dim; ++k) {
      sum += e.grad_p1(k);
      for (int j = 0; j <= dim; ++j) EXPECT_NEAR(e.p1(k, e.a[j]), k == j ? 1.0 : 0.0, 1e-12);
    }
    EXPECT_LT(sum.norm(), 1e-10 / std::pow(e.measure, 1.0 / dim));
  }
}

TYPED_TEST(SimplexElementTest, QuadratureIsExactForProductsOfP1Functions) {
  constexpr int dim = TypeParam::value;
  const SimplexMesh<dim> mesh = test_mesh<dim>();
  for (int t = 0; t < mesh.num_cells(); t += 3) {
    const SimplexElement<dim> e(mesh, t);
    const auto points = e.quadrature_points();
    for (int a = 0; a <= dim; ++a)
      for (int b = 0; b <= dim; ++b) {
        double integral = 0.0;
        for (const Vec<dim>& x : points)
          integral += e.quadrature_weight() * e.p1(a, x) * e.p1(b, x);
        // ∫_T λ_a λ_b = |T| (1 + δ_ab) / ((d + 1)(d + 2)).
        const double exact = e.measure * (a == b ? 2.0 : 1.0) / ((dim + 1) * (dim + 2));
        EXPECT_NEAR(integral, exact, 1e-12 * e.measure);
      }
  }
}

}  // namespace
}  // namespace fosls
