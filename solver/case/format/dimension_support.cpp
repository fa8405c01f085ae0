#include "case/format/dimension_support.hpp"

namespace fosls {

namespace {

void check_contact(const std::string& name, const BoundaryCondition& bc,
                   std::vector<CaseError>& errors) {
  const std::string at = child_pointer("/boundary", name);
  if (bc.frictional())
    errors.push_back({child_pointer(at, "friction"),
                      "friction is 2D only for now: in 3D the tangential bound is a disc, not a "
                      "box, and the solvers' bounds are boxes; it is coming. Remove friction for "
                      "a frictionless 3D contact"});
}

}  // namespace

std::vector<CaseError> dimension_support_problems(const nlohmann::json& j, const CaseSpec& spec) {
  std::vector<CaseError> errors;
  if (spec.dimension != 3) return errors;
  if (spec.mesh.order == 2)
    errors.push_back({"/mesh/order",
                      "order 2 is 2D only for now: the order-2 space P2 × RT1 is built on "
                      "triangles; use mesh.order 1 and more mesh.refinements"});
  if (spec.solver.stopping == StoppingRule::kDiscretisation)
    errors.push_back(
        {"/solver/tolerance",
         "\"discretisation\" is 2D only for now: its estimate bounds the algebraic error in the "
         "functional's norm, and in 3D that left the Hertz ball's force up to 5 % short of the "
         "converged one at λ = \"inf\" (docs/case-format.md); give a number, e.g. 1e-8"});
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact) check_contact(name, bc, errors);
  return errors;
}

}  // namespace fosls
