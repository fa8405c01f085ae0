// What a user is told when the FOSLS matrix is not positive definite (indefinite_weights.hpp).

#include "case/run/indefinite_weights.hpp"

#include <sstream>

#include "assembly/contact_weight.hpp"

namespace fosls {

namespace {

bool has_roller(const CaseSpec& spec, int dim) {
  for (const auto& [name, bc] : spec.boundary) {
    if (bc.type != BoundaryCondition::Type::kDirichlet) continue;
    for (int c = 0; c < dim; ++c)
      if (!bc.prescribed[c]) return true;
  }
  return false;
}

/// The body's smallest and largest extent along the axes.
template <int dim>
std::pair<double, double> extents(const SimplexMesh<dim>& mesh) {
  Vec<dim> lo = mesh.vertex(0), hi = mesh.vertex(0);
  for (int v = 1; v < mesh.num_vertices(); ++v) {
    lo = lo.cwiseMin(mesh.vertex(v));
    hi = hi.cwiseMax(mesh.vertex(v));
  }
  return {(hi - lo).minCoeff(), (hi - lo).maxCoeff()};
}

}  // namespace

template <int dim>
CaseException indefinite_weights(const CaseSpec& used, const SimplexMesh<dim>& coarse,
                                 const ProblemData<dim>& data, const std::string& found) {
  std::ostringstream m;
  const auto [thinnest, widest] = extents<dim>(coarse);
  if (thinnest < kThinnestBody * widest) {
    m << "the body is " << thinnest << " thin and " << widest << " across (a ratio of "
      << thinnest / widest
      << "): its FOSLS matrix is not positive definite in double precision. Model a body this "
         "thin "
      << (dim == 3 ? "as a plate or a 2D case" : "as a beam") << ", or make it thicker";
    return CaseException("/mesh", m.str());
  }
  const Weights& w = used.weights;
  m << "the weights c1 = " << w.c1 << ", c2 = " << w.c2 << ", c3 = " << w.c3 << ", c4 = " << w.c4
    << ", c2_volumetric = " << w.c2_volumetric
    << " make the FOSLS matrix indefinite (the contact term c3 is too large relative to c1 and "
       "c2)";
  if (w.c3_auto) {
    m << "; c3 was chosen as half the limit " << w.c3_limit
      << " computed on a coarser level, and the finest level's limit is lower: set c3 below "
         "that by hand";
  } else {
    const ContactWeightLimit limit =
        contact_weight_limit(build_uniform_hierarchy(coarse, used.mesh.refinements), data);
    m << "; on this mesh c3 must stay below about " << limit.limit << " (computed on level "
      << limit.level << ", " << limit.dofs
      << " unknowns): remove c3 from the case (or give \"auto\") to have it chosen";
  }
  // A body held only by rollers may keep a rigid motion: that looks the same to the check.
  if (has_roller(used, dim))
    m << ". With null displacement components, also check that the dirichlet groups leave no "
         "rigid motion (a rotation needs two points held across it)";
  if (!found.empty()) m << " (found by the solver: " << found << ")";
  return CaseException("/weights", m.str());
}

template CaseException indefinite_weights<2>(const CaseSpec&, const Mesh&, const ProblemData<2>&,
                                             const std::string&);
template CaseException indefinite_weights<3>(const CaseSpec&, const TetMesh&, const ProblemData<3>&,
                                             const std::string&);

}  // namespace fosls
