#include "case/dimension_support.hpp"

#include "case/solver_methods.hpp"

namespace fosls {

namespace {

/// Sections whose loops run several solves or choose the levels: coming with the one
/// finite-element stack for both dimensions (docs/architecture.md, "One case path for 2D and 3D").
struct Section {
  const char* key;
  const char* why;
};

constexpr Section kComing[] = {
    {"load_steps",
     "load steps are 2D only for now (they come to 3D with the one finite-element stack); "
     "solve each state as a case of its own"},
    {"sweep",
     "sweeps are 2D only for now (they come to 3D with the one finite-element stack); solve "
     "each value as a case of its own"},
};

void check_contact(const std::string& name, const BoundaryCondition& bc,
                   std::vector<CaseError>& errors) {
  const std::string at = child_pointer("/boundary", name);
  if (bc.frictional())
    errors.push_back({child_pointer(at, "friction"),
                      "friction is 2D only for now: in 3D the tangential bound is a disc, not a "
                      "box, and the solvers' bounds are boxes; it is coming. Remove friction for "
                      "a frictionless 3D contact"});
  if (bc.direction == ContactDirection::kObstacleNormal)
    errors.push_back({child_pointer(at, "direction"),
                      "obstacle_normal is 2D only for now: a 3D contact is constrained along the "
                      "body normal (body_normal, the default); the obstacle's normal comes with "
                      "the 3D contact frames of the one finite-element stack"});
}

}  // namespace

std::vector<CaseError> dimension_support_problems(const nlohmann::json& j, const CaseSpec& spec) {
  std::vector<CaseError> errors;
  if (spec.dimension != 3) return errors;
  for (const Section& s : kComing)
    if (j.contains(s.key)) errors.push_back({std::string("/") + s.key, s.why});
  if (spec.mesh.order == 2)
    errors.push_back({"/mesh/order",
                      "order 2 is 2D only for now: the order-2 space P2 × RT1 is built on "
                      "triangles; use mesh.order 1 and more mesh.refinements"});
  if (!runs_in(spec.solver.method, 3))
    errors.push_back({"/solver/method", "a 3D case is solved by mmg (the default) or pdas"});
  if (spec.solver.stopping == StoppingRule::kDiscretisation)
    errors.push_back(
        {"/solver/tolerance",
         "\"discretisation\" is 2D only for now: in 3D its estimate of the algebraic error "
         "stopped the Hertz ball 4 % (refinements 2) to 44 % (refinements 1) short of the "
         "converged force, until the 3D functional is scaled like 2D's (its length scale); give "
         "a number, e.g. 1e-8"});
  const auto& weights = j.value("weights", nlohmann::json::object());
  if (weights.is_object() && weights.value("c3", nlohmann::json()) == "auto")
    errors.push_back({"/weights/c3",
                      "\"auto\" is 2D only for now: it chooses c3 from the definiteness limit "
                      "of the 2D contact term on the coarse levels, which 3D does not compute "
                      "yet; give a number (3D's default is 0.1)"});
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact) check_contact(name, bc, errors);
  return errors;
}

}  // namespace fosls
