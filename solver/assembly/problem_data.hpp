#pragma once
// The continuous problem handed to the assembler, in 2D and 3D: material, weights, data as
// functions, and the rigid obstacles of the contact groups. Plain structs of this layer; the
// case layer converts a validated case into them.

#include <array>
#include <functional>
#include <limits>
#include <type_traits>
#include <vector>

#include "fem/fosls_space.hpp"

namespace fosls {

using ScalarFunction = std::function<double(double x, double y)>;
using ScalarFunction3d = std::function<double(double x, double y, double z)>;

/// A scalar field of R^dim: a function of (x, y) or of (x, y, z).
template <int dim>
using ScalarFunctionOf = std::conditional_t<dim == 2, ScalarFunction, ScalarFunction3d>;

/// f(x) for a point of R^dim.
template <int dim>
double evaluate(const ScalarFunctionOf<dim>& f, const Vec<dim>& x) {
  if constexpr (dim == 2)
    return f(x.x(), x.y());
  else
    return f(x.x(), x.y(), x.z());
}

/// Lamé parameters of an isotropic material (plane strain in 2D).
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
  /// Weight of the volumetric part (tr(Aσ − ε(u)))²/d of the c2 term against its deviatoric
  /// part (1: the Frobenius norm; docs/method.md §2.2).
  double c2_volumetric = 1.0;
};

/// A rigid obstacle: a plane, a ball (a disk in 2D, the body outside it), or a gap given as a
/// function.
template <int dim>
struct RigidObstacle {
  enum class Kind { kPlane, kBall, kGap };
  Kind kind = Kind::kPlane;
  Vec<dim> point = Vec<dim>::Zero();          ///< plane: a point on it
  Vec<dim> normal = Vec<dim>::Unit(dim - 1);  ///< plane: unit normal into the body
  Vec<dim> center = Vec<dim>::Zero();         ///< ball
  double radius = 0.0;                        ///< ball
};

/// Along which direction the constraint u·d ≤ g is imposed (docs/method.md §1).
enum class ConstraintDirection { kBodyNormal, kObstacleNormal };

/// Friction on a contact group (docs/method.md §8, 2D): Coulomb |σ_nt| ≤ 𝔣 |σ_nn| when
/// coefficient > 0, else Tresca |σ_nt| ≤ s(x) when `bound` is set, else none.
template <int dim>
struct FrictionData {
  double coefficient = 0.0;
  ScalarFunctionOf<dim> bound;
  bool coulomb() const { return coefficient > 0.0; }
  bool frictional() const { return coulomb() || static_cast<bool>(bound); }
};

/// Contact data of one group: the rigid obstacle and the constraint direction (docs/method.md
/// §1).
template <int dim>
struct ContactData {
  RigidObstacle<dim> obstacle;
  ScalarFunctionOf<dim> gap;  ///< g(x) along the body normal, for RigidObstacle::Kind::kGap
  ConstraintDirection direction = ConstraintDirection::kBodyNormal;
  FrictionData<dim> friction;
};

/// Boundary condition of one mesh group.
template <int dim>
struct GroupData {
  GroupRole role = GroupRole::kNeumann;
  /// kDirichlet: the components prescribed, bit c for u_c (a roller or symmetry plane
  /// prescribes some; BoundaryRole::prescribed).
  int prescribed = kEveryComponent;
  /// u_D (Dirichlet) or t_N (Neumann), Cartesian; an empty component is zero.
  std::array<ScalarFunctionOf<dim>, dim> values;
  /// Neumann: values[0] is a normal pressure p, the traction t = −p n (n the outward normal).
  bool normal_pressure = false;
  ContactData<dim> contact;
};

template <int dim>
struct ProblemData {
  ElasticMaterial material;
  FunctionalWeights weights;
  std::array<ScalarFunctionOf<dim>, dim> body_force;  ///< an empty component is zero
  std::vector<GroupData<dim>> groups;                 ///< indexed like the mesh's group_names()

  /// The displacement of each vertex of the finest mesh that friction measures slip from: the
  /// state a load step starts from (empty: zero).
  std::vector<Vec<dim>> reference_displacement;

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
template <int dim>
struct ContactPoint {
  Vec<dim> direction;
  double gap;
};

/// The obstacle of `c` seen from p with outward unit normal n, along c.direction or, when
/// given, `direction`.
template <int dim>
ContactPoint<dim> locate_obstacle(const ContactData<dim>& c, const Vec<dim>& p,
                                  const Vec<dim>& body_normal);
template <int dim>
ContactPoint<dim> locate_obstacle(const ContactData<dim>& c, const Vec<dim>& p,
                                  const Vec<dim>& body_normal, ConstraintDirection direction);

/// A gap where the ray misses the obstacle (+∞) or one far beyond the body, capped at ten times
/// the body's diameter: the vertex is then effectively unconstrained and the functional's gap
/// term stays finite. The one cap of every space (P1–RT0 in 2D and 3D, order 2).
double capped_gap(double gap, double body_diameter);

/// Constraint directions at contact vertices for groups that constrain along the obstacle
/// normal (docs/method.md §1); empty when every contact group uses the body normal.
template <int dim>
std::vector<Vec<dim>> obstacle_vertex_normals(const SimplexMesh<dim>& mesh,
                                              const ProblemData<dim>& data);

}  // namespace fosls
