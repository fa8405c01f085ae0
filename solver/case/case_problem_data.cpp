#include "case/case_problem_data.hpp"

#include <string>

#include "case/case_error.hpp"
#include "case/expression.hpp"

namespace fosls {

namespace {

RigidObstacle<2> rigid_obstacle(const Obstacle& o) {
  RigidObstacle<2> r;
  r.kind = o.kind == Obstacle::Kind::kPlane  ? RigidObstacle<2>::Kind::kPlane
           : o.kind == Obstacle::Kind::kBall ? RigidObstacle<2>::Kind::kBall
                                             : RigidObstacle<2>::Kind::kGap;
  // The reader normalised the normal; normalised once more, as locate_obstacle did before it
  // took unit normals, so that 2D results stay bit for bit.
  r.point = o.point.head<2>(), r.normal = o.normal.head<2>().normalized();
  r.center = o.center.head<2>(), r.radius = o.radius;
  return r;
}

}  // namespace

/// The case in the assembly layer's terms.
ProblemData<2> problem_data(const CaseSpec& spec, const Mesh& mesh) {
  ProblemData<2> d;
  d.material = {.mu = spec.material.mu, .lambda = spec.material.lambda};
  const Weights& w = spec.weights;
  // The c1 term in units of the body's size (mesh/length_scale.hpp).
  const double l = w.length_scale;
  d.weights = {
      .c1 = w.c1 * l * l, .c2 = w.c2, .c3 = w.c3, .c4 = w.c4, .c2_volumetric = w.c2_volumetric};
  // A zero component stays empty: the assembler then stores no body force at all.
  for (int i = 0; i < 2; ++i)
    if (const Scalar& f = spec.body_force[i]; !f.is_constant() || f.value != 0.0)
      d.body_force[i] = compile_scalar(f);
  d.groups.resize(mesh.group_names().size());  // unnamed groups: traction free
  for (const auto& [name, bc] : spec.boundary) {
    GroupData<2>& g = d.groups[mesh.group_index(name)];
    switch (bc.type) {
      case BoundaryCondition::Type::kDirichlet:
        g.role = GroupRole::kDirichlet;
        g.prescribed = (bc.prescribed[0] ? 1 : 0) | (bc.prescribed[1] ? 2 : 0);
        break;
      case BoundaryCondition::Type::kNeumann:
        g.role = GroupRole::kNeumann;
        break;
      case BoundaryCondition::Type::kPressure:
        g.role = GroupRole::kNeumann;
        g.normal_pressure = true;
        break;
      case BoundaryCondition::Type::kContact:
        g.role = GroupRole::kContact;
        g.contact.obstacle = rigid_obstacle(bc.obstacle);
        g.contact.direction = bc.direction == ContactDirection::kBodyNormal
                                  ? ConstraintDirection::kBodyNormal
                                  : ConstraintDirection::kObstacleNormal;
        if (bc.obstacle.kind == Obstacle::Kind::kGap)
          g.contact.gap = compile_scalar(bc.obstacle.gap);
        g.contact.friction.coefficient = bc.friction_coefficient;
        if (bc.friction_bound)
          g.contact.friction.bound = [s = compile_scalar(*bc.friction_bound),
                                      pointer = "/boundary/" + name + "/friction/bound"](double x,
                                                                                         double y) {
            const double value = s(x, y);
            if (!(value >= 0.0))
              throw CaseException(pointer, "the slip bound is " + std::to_string(value) + " at (" +
                                               std::to_string(x) + ", " + std::to_string(y) +
                                               "); it must be >= 0");
            return value;
          };
        break;
    }
    if (bc.type != BoundaryCondition::Type::kContact)
      for (int i = 0; i < 2; ++i) g.values[i] = compile_scalar(bc.values[i]);
  }
  return d;
}

}  // namespace fosls
