#pragma once
// The continuous problem handed to the assembler: material, weights, data as functions.
// Plain structs of this layer; the case layer converts a validated case into them.

#include <array>
#include <functional>
#include <limits>
#include <vector>

#include "fem/fosls_space.hpp"

namespace fosls {

using ScalarFunction = std::function<double(double x, double y)>;

/// Lamé parameters of an isotropic material (plane strain).
struct ElasticMaterial {
  double mu = 1.0;
  double lambda = 1.0;  ///< +infinity for an incompressible material
  bool incompressible() const { return lambda == std::numeric_limits<double>::infinity(); }
};

/// Weights of the terms of the FOSLS functional (docs/method.md §2): c1 ‖div σ + f‖²,
/// c2 ‖Aσ − ε(u)‖², c3 ⟨u·n − g, σ_nn⟩, c4 ‖as σ‖². The defaults are the method's (c3 small
/// enough to keep the functional convex, see README "Decisions").
struct FunctionalWeights {
  double c1 = 1.0;
  double c2 = 1.0;
  double c3 = 0.1;
  double c4 = 0.0;
  /// Weight of the volumetric part ½ (tr(Aσ − ε(u)))² of the c2 term against its deviatoric
  /// part (1: the Frobenius norm; docs/method.md §2.2).
  double c2_volumetric = 1.0;
};

/// A rigid obstacle: a plane, the outside of a circle, or a gap given as a function.
struct RigidObstacle {
  enum class Kind { kPlane, kCircle, kGap };
  Kind kind = Kind::kPlane;
  Point point = Point::Zero();   ///< plane: a point on it
  Point normal = Point(0, 1);    ///< plane: unit normal from the obstacle into the body
  Point center = Point::Zero();  ///< circle
  double radius = 0.0;           ///< circle (the body lies outside the circle)
};

/// Along which direction the constraint u·d ≤ g is imposed (docs/method.md §1).
enum class ConstraintDirection { kBodyNormal, kObstacleNormal };

/// Friction on a contact group (docs/method.md §8): Coulomb |σ_nt| ≤ 𝔣 |σ_nn| when coefficient
/// > 0, else Tresca |σ_nt| ≤ s(x, y) when `bound` is set, else none.
struct FrictionData {
  double coefficient = 0.0;
  ScalarFunction bound;
  bool coulomb() const { return coefficient > 0.0; }
  bool frictional() const { return coulomb() || static_cast<bool>(bound); }
};

/// Contact data of one group: the rigid obstacle and the constraint direction (docs/method.md
/// §1).
struct ContactData {
  RigidObstacle obstacle;
  ScalarFunction gap;  ///< g(x, y) along the body normal, for RigidObstacle::Kind::kGap
  ConstraintDirection direction = ConstraintDirection::kBodyNormal;
  FrictionData friction;
};

/// Boundary condition of one mesh group.
struct GroupData {
  GroupRole role = GroupRole::kNeumann;
  /// kDirichlet: the components prescribed, bit c for u_c (a roller or symmetry plane
  /// prescribes some; BoundaryRole::prescribed).
  int prescribed = kEveryComponent;
  std::array<ScalarFunction, 2> values;  ///< u_D (Dirichlet) or t_N (Neumann), Cartesian
  /// Neumann: values[0] is a normal pressure p, the traction t = −p n (n the outward normal).
  bool normal_pressure = false;
  ContactData contact;
};

struct ProblemData {
  ElasticMaterial material;
  FunctionalWeights weights;
  std::array<ScalarFunction, 2> body_force;  ///< an empty component is zero
  std::vector<GroupData> groups;             ///< indexed like Mesh::group_names()

  /// The displacement of each vertex of the finest mesh that friction measures slip from: the
  /// state a load step starts from (empty: zero).
  std::vector<Point> reference_displacement;

  /// What each group makes of the DOFs on it (FoslsSpace).
  std::vector<BoundaryRole> boundary_roles() const {
    std::vector<BoundaryRole> r;
    for (const auto& g : groups)
      r.push_back(
          {g.role, g.prescribed, g.role == GroupRole::kContact && g.contact.friction.frictional()});
    return r;
  }
};

/// Where the obstacle is seen from a boundary point: the constraint direction d (unit) and the
/// gap g ≥ u·d, measured along d. A point whose ray misses the obstacle gets an infinite gap.
struct ContactPoint {
  Point direction;
  double gap;
};
ContactPoint locate_obstacle(const ContactData& c, const Point& p, const Point& body_normal);

}  // namespace fosls
