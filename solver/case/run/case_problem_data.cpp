#include "case/run/case_problem_data.hpp"

#include <string>

#include "assembly/contact_weight.hpp"
#include "case/format/case_error.hpp"
#include "case/format/expression.hpp"

namespace fosls {

namespace {

/// A case's scalar as a function of the dimension's coordinates.
template <int dim>
ScalarFunctionOf<dim> compile(const Scalar& s) {
  if constexpr (dim == 2)
    return compile_scalar(s);
  else
    return compile_scalar_3d(s);
}

template <int dim>
RigidObstacle<dim> rigid_obstacle(const Obstacle& o) {
  using Kind = typename RigidObstacle<dim>::Kind;
  RigidObstacle<dim> r;
  r.kind = o.kind == Obstacle::Kind::kPlane  ? Kind::kPlane
           : o.kind == Obstacle::Kind::kBall ? Kind::kBall
                                             : Kind::kGap;
  // The reader normalised the normal; in 2D normalised once more, as locate_obstacle did before
  // it took unit normals, so that 2D results stay bit for bit.
  if constexpr (dim == 2)
    r.normal = o.normal.head<2>().normalized();
  else
    r.normal = o.normal;
  r.point = o.point.head<dim>(), r.center = o.center.head<dim>(), r.radius = o.radius;
  return r;
}

/// Tresca's slip bound as a function that refuses a negative value where it is evaluated (2D;
/// 3D refuses friction when the case is read).
ScalarFunction slip_bound(const Scalar& bound, const std::string& name) {
  return [s = compile_scalar(bound), pointer = "/boundary/" + name + "/friction/bound"](double x,
                                                                                        double y) {
    const double value = s(x, y);
    if (!(value >= 0.0))
      throw CaseException(pointer, "the slip bound is " + std::to_string(value) + " at (" +
                                       std::to_string(x) + ", " + std::to_string(y) +
                                       "); it must be >= 0");
    return value;
  };
}

template <int dim>
void set_contact(ContactData<dim>& c, const BoundaryCondition& bc, const std::string& name) {
  c.obstacle = rigid_obstacle<dim>(bc.obstacle);
  c.direction = bc.direction == ContactDirection::kBodyNormal
                    ? ConstraintDirection::kBodyNormal
                    : ConstraintDirection::kObstacleNormal;
  if (bc.obstacle.kind == Obstacle::Kind::kGap) c.gap = compile<dim>(bc.obstacle.gap);
  if constexpr (dim == 2) {
    c.friction.coefficient = bc.friction_coefficient;
    if (bc.friction_bound) c.friction.bound = slip_bound(*bc.friction_bound, name);
  }
}

}  // namespace

template <int dim>
ProblemData<dim> problem_data(const CaseSpec& spec, const SimplexMesh<dim>& mesh) {
  ProblemData<dim> d;
  d.material = {.mu = spec.material.mu, .lambda = spec.material.lambda};
  const Weights& w = spec.weights;
  // The c1 term in units of the body's size (mesh/length_scale.hpp).
  const double l = w.length_scale;
  d.weights = {
      .c1 = w.c1 * l * l, .c2 = w.c2, .c3 = w.c3, .c4 = w.c4, .c2_volumetric = w.c2_volumetric};
  // A zero component stays empty: the assembler then stores no body force at all.
  for (int i = 0; i < dim; ++i)
    if (const Scalar& f = spec.body_force[i]; !f.is_constant() || f.value != 0.0)
      d.body_force[i] = compile<dim>(f);
  d.groups.resize(mesh.group_names().size());  // unnamed groups: traction free
  for (const auto& [name, bc] : spec.boundary) {
    GroupData<dim>& g = d.groups[mesh.group_index(name)];
    switch (bc.type) {
      case BoundaryCondition::Type::kDirichlet:
        g.role = GroupRole::kDirichlet;
        g.prescribed = 0;
        for (int i = 0; i < dim; ++i) g.prescribed |= bc.prescribed[i] ? 1 << i : 0;
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
        set_contact<dim>(g.contact, bc, name);
        break;
    }
    if (bc.type != BoundaryCondition::Type::kContact)
      for (int i = 0; i < dim; ++i) g.values[i] = compile<dim>(bc.values[i]);
  }
  return d;
}

template <int dim>
void choose_contact_weight(CaseSpec& used, const SimplexHierarchy<dim>& meshes,
                           ProblemData<dim>& data) {
  if (!used.weights.c3_auto || !has_contact(used)) return;
  const ContactWeightLimit limit = contact_weight_limit(meshes, data);
  used.weights.c3_limit = limit.limit;
  used.weights.c3 = data.weights.c3 = automatic_contact_weight(limit);
}

template ProblemData<2> problem_data<2>(const CaseSpec&, const SimplexMesh<2>&);
template ProblemData<3> problem_data<3>(const CaseSpec&, const SimplexMesh<3>&);
template void choose_contact_weight<2>(CaseSpec&, const SimplexHierarchy<2>&, ProblemData<2>&);
template void choose_contact_weight<3>(CaseSpec&, const SimplexHierarchy<3>&, ProblemData<3>&);

}  // namespace fosls
