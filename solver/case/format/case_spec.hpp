#pragma once
// The contact case as the library sees it after the case JSON has been validated, in 2D or 3D
// (`dimension`). Vectors have three components; a 2D case uses the first two (docs/architecture.md,
// "One case path for 2D and 3D"). The JSON format is documented in docs/case-format.md; reading
// lives in case_reader.hpp, the format's rules in the case_sections.hpp files.

#include <array>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "case/format/units.hpp"
#include "mesh/geometry_spec.hpp"
#include "mesh/tet_half_ball.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

/// A scalar datum: a number, or an expression of x and y (and z in 3D; muParser syntax).
struct Scalar {
  std::string expression;  ///< empty when `value` is a plain number
  double value = 0.0;
  bool is_constant() const { return expression.empty(); }
};

struct MeshSpec {
  enum class Kind { kBuiltin, kGeometry, kMsh, kGeoFile };
  Kind kind = Kind::kBuiltin;
  std::string builtin = "square";        ///< "square" or "hertz" (2D), "box" or "half_ball" (3D)
  std::map<std::string, double> params;  ///< 2D builtin parameters (x0, y0, width, height; radius,
                                         ///< contact_fraction, grading)
  std::array<int, 3> box_cells = {2, 2, 2};  ///< box: cubes (six tetrahedra each) per direction
  Point3 box_lengths = Point3(1, 1, 1);      ///< box: [0, lx] × [0, ly] × [0, lz]
  HalfBallSpec half_ball;                    ///< half_ball
  GeometrySpec geometry;                     ///< kind == kGeometry
  std::string msh_text;                      ///< kind == kMsh (ASCII 4.1)
  std::string msh_path;  ///< kind == kMsh read from mesh.msh_file (CLI only), else empty
  std::string geo_path;  ///< kind == kGeoFile (CLI only, never from the network)
  double size = 0.25;    ///< coarse mesh size (3D: geo_file only)
  int refinements = 0;   ///< levels = refinements + 1
  /// Polynomial order of the space on the finest mesh: 1 (P1 × RT0) or 2 (P2 × RT1 on top of
  /// the lowest-order hierarchy, docs/method.md §10).
  int order = 1;
};

struct Material {
  double mu = 1.0;
  double lambda = 1.0;  ///< +infinity for an incompressible material
  bool incompressible() const { return lambda == std::numeric_limits<double>::infinity(); }
};

/// A rigid obstacle; its points and vectors have a zero third component in 2D.
struct Obstacle {
  enum class Kind { kPlane, kBall, kGap };
  Kind kind = Kind::kPlane;
  Point3 point = Point3::Zero();    ///< plane: a point on it
  Point3 normal = Point3(0, 1, 0);  ///< plane: unit normal from the obstacle into the body
  Point3 center = Point3::Zero();   ///< ball: a circle (2D) or sphere (3D)
  double radius = 0.0;              ///< ball (the body lies outside it)
  Scalar gap;                       ///< gap: g(x, y) measured along the body normal
  /// The obstacle's rigid displacement, already added to point and center (a prescribed
  /// indentation: result_warnings.hpp tells it from an initial overlap).
  Point3 displacement = Point3::Zero();
  /// A plane given by the contact condition's own point and normal, not as `obstacle`: where
  /// problems of its normal are reported.
  bool short_form = false;
};

enum class ContactDirection { kBodyNormal, kObstacleNormal };

struct BoundaryCondition {
  enum class Type { kDirichlet, kNeumann, kPressure, kContact };
  Type type = Type::kNeumann;
  /// displacement (Dirichlet), traction (Neumann) or [p, 0, 0] (pressure); 2D uses two
  std::array<Scalar, 3> values;
  /// Dirichlet: false for a component given as null, which is free with zero traction (a
  /// roller or symmetry plane).
  std::array<bool, 3> prescribed = {true, true, true};
  Obstacle obstacle;  ///< contact
  ContactDirection direction = ContactDirection::kBodyNormal;
  /// Contact: Coulomb's coefficient 𝔣 (0: none), or Tresca's slip bound s (docs/method.md §8).
  double friction_coefficient = 0.0;
  std::optional<Scalar> friction_bound;
  bool frictional() const { return friction_coefficient > 0.0 || friction_bound.has_value(); }
};

/// Weights of the FOSLS functional (docs/method.md §2).
struct Weights {
  double c1 = 1.0;
  double c2 = 1.0;
  /// The weight used; with c3_auto it is chosen from the mesh when the case runs
  /// (assembly/contact_weight.hpp) and `c3_limit` records the limit it was chosen from.
  double c3 = 0.1;
  double c4 = 0.0;
  double c2_volumetric = 1.0;  ///< docs/method.md §2.2
  bool c3_auto = true;
  double c3_limit = 0.0;  ///< 0 when not computed
  /// ℓ of mesh/length_scale.hpp, set when the case runs: the c1 term is weighted c1 ℓ².
  double length_scale = 1.0;
};

/// The `adaptivity` section: solve → estimate → mark → refine by newest-vertex bisection →
/// solve again from the prolongated solution, until one of the limits stops it.
struct AdaptivitySpec {
  int steps = 10;                ///< refinement steps at most (steps + 1 solves)
  long long max_dofs = 200'000;  ///< a refinement that would give more DOFs is not made
  /// Dörfler parameter: refine the triangles of θ of J. 0.7 against 0.5, 0.6 and 0.8: the
  /// same accuracy per unknown in less time, since fewer steps are solved (docs/validation.md
  /// §10; docs/performance.md, "Measurements behind choices in the code").
  double theta = 0.7;
  /// Stop once the estimator J^½ has fallen to `target` times its value on the starting mesh
  /// (0: no target).
  double target = 0.0;
};

/// The `accuracy` section: solve, estimate the contact force's error from the forces of the
/// levels solved so far, refine (adaptively by default in 3D, uniformly in 2D) and
/// solve again from the prolongated solution, until the estimate is below `force` or the next
/// level would exceed `max_dofs` (docs/method.md §9).
struct AccuracySpec {
  double force = 1e-3;             ///< requested relative error of the contact force |F|
  long long max_dofs = 2'000'000;  ///< a refinement that would give more DOFs is not made
  /// Dörfler marking and bisection between the levels; false: uniform (red) refinement. Set
  /// when the case is read (settle_accuracy_refinement).
  bool adaptive = true;
  bool refinement_given = false;  ///< the case says `refinement` (it is not the default)
  double theta = 0.7;             ///< the Dörfler parameter of adaptive levels (as adaptivity's)
};

/// A number of the case that takes several values (the case's `sweep`).
struct SweepSpec {
  std::string pointer;  ///< JSON pointer into the case
  std::vector<double> values;
};

struct CaseSpec {
  std::string name = "case";
  /// 2: plane strain on triangles; 3: a body of tetrahedra. What 3D cannot do yet is refused
  /// when the case is read (dimension_support.hpp).
  int dimension = 2;
  MeshSpec mesh;
  Material material;
  std::array<Scalar, 3> body_force;  ///< 2D uses two
  /// Condition per boundary group; groups not named are traction free.
  std::map<std::string, BoundaryCondition> boundary;
  Weights weights;
  SolverOptions solver;  ///< the case's `solver` section (method, tolerance, smoothing, ...)
  std::optional<AdaptivitySpec> adaptivity;  ///< absent: uniform refinement only
  std::optional<AccuracySpec> accuracy;      ///< absent: the levels of mesh.refinements only
  std::optional<SweepSpec> sweep;
  UnitsSpec units;  ///< the case's `units`; none declared by default (units.hpp)
  /// With a sweep: the case at each value, in order (without a sweep of their own).
  std::vector<CaseSpec> sweep_points;
  /// With load steps: the case after each step, in order, and each step's changes (pointer →
  /// value); the case itself is step 0's state before the first step (docs/case-format.md,
  /// "Load steps").
  std::vector<CaseSpec> load_step_points;
  std::vector<nlohmann::json> load_step_changes;
};

/// Whether some boundary group of the case is a contact condition.
inline bool has_contact(const CaseSpec& spec) {
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact) return true;
  return false;
}

/// Whether some contact group of the case has friction (Tresca or Coulomb).
inline bool has_friction(const CaseSpec& spec) {
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact && bc.frictional()) return true;
  return false;
}

/// Whether `method` may solve the case; the reader refuses the others (case_reader.cpp): tnnmg
/// has no friction, and order 2 is solved by mmg or pdas only. The admission's advice offers
/// only these.
inline bool method_solves(SolverMethod method, const CaseSpec& spec) {
  if (method == SolverMethod::kTnnmg && has_friction(spec)) return false;
  return spec.mesh.order != 2 || method == SolverMethod::kMmg || method == SolverMethod::kPdas;
}

}  // namespace fosls
