#pragma once
// 3D problems shared by the 3D tests and fosls-bench-3d.
#include <cmath>
#include <limits>

#include "assembly/tet_hierarchy.hpp"
#include "post/contact_force.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls::testing {

/// A function of a point as the function of (x, y, z) that the problem data take.
inline ScalarFunction3d of_point(std::function<double(const Point3&)> f) {
  return [f = std::move(f)](double x, double y, double z) { return f(Point3(x, y, z)); };
}

/// The 3D Signorini block: the unit cube pressed down by 0.05 at its top (Dirichlet) onto the
/// gap 0.4 ((x − ½)² + (y − ½)²) below its bottom (contact), traction-free sides; the groups of
/// make_box.
inline ProblemData<3> signorini_block(double lambda) {
  ProblemData<3> d;
  d.material = {.mu = 1.0, .lambda = lambda};
  d.groups.resize(6);  // left, right, front, back, bottom, top
  d.groups[4].role = GroupRole::kContact;
  d.groups[4].contact.obstacle.kind = RigidObstacle<3>::Kind::kGap;
  d.groups[4].contact.gap = [](double x, double y, double) {
    return 0.4 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5));
  };
  d.groups[5].role = GroupRole::kDirichlet;
  d.groups[5].values[2] = [](double, double, double) { return -0.05; };
  return d;
}

/// The 3D Hertz problem on make_half_ball's groups (top, contact, free): the half ball of
/// radius 1 clamped at its flat top and pressed down by δ onto the plane z = −1 that touches its
/// pole; the gap along the body normal x/|x|, traction-free elsewhere. Hertz: F = 4/3 E* √R δ^1.5
/// with E* = 2μ/(1 − ν) (= 8/3 for μ = λ = 1).
inline ProblemData<3> hertz_half_ball(double lambda, double delta = 0.01) {
  ProblemData<3> d;
  d.material = {.mu = 1.0, .lambda = lambda};
  d.groups.resize(3);
  d.groups[0].role = GroupRole::kDirichlet;
  d.groups[0].values[2] = [delta](double, double, double) { return -delta; };
  d.groups[1].role = GroupRole::kContact;
  d.groups[1].contact.obstacle.kind = RigidObstacle<3>::Kind::kGap;
  d.groups[1].contact.gap = of_point([](const Point3& x) {
    const double approach = -x.z() / x.norm();  // how directly the body normal meets the plane
    return approach > 1e-12 ? (x.z() + 1.0) / approach : std::numeric_limits<double>::infinity();
  });
  return d;
}

/// E* = E/(1 − ν²) = 2μ/(1 − ν) for μ = 1.
inline double hertz_modulus_3d(double lambda) {
  const double nu = std::isinf(lambda) ? 0.5 : lambda / (2.0 * (lambda + 1.0));
  return 2.0 / (1.0 - nu);
}

inline double hertz_force_3d(double lambda, double delta = 0.01) {
  return 4.0 / 3.0 * hertz_modulus_3d(lambda) * std::pow(delta, 1.5);
}

/// Hertz's contact radius and peak pressure for the force F on a sphere of radius 1:
/// a = (3F/(4E*))^⅓, p0 = 3F/(2πa²).
inline double hertz_radius_3d(double lambda, double force) {
  return std::cbrt(3.0 * force / (4.0 * hertz_modulus_3d(lambda)));
}
inline double hertz_peak_3d(double lambda, double force) {
  const double a = hertz_radius_3d(lambda, force);
  return 3.0 * force / (2.0 * M_PI * a * a);
}

/// One discrete 3D contact problem solved by mmg and by pdas to a relative KKT residual of
/// 10⁻¹⁰, so that their forces compare to 10⁻⁶.
struct MmgAndPdas {
  SolverReport mmg, pdas;
  Point3 force, pdas_force;
};

inline MmgAndPdas solve_with_mmg_and_pdas(const TetDiscretization& disc, const LevelHierarchy& h) {
  const BoxQp& qp = disc.problem().qp;
  const FoslsAssembler<3>& a = disc.assembler();
  const double scale = disc.problem().stress_scale;
  MmgAndPdas out;
  SolverOptions options;
  options.tolerance = 1e-10;
  Vector x = Vector::Zero(qp.size());
  out.mmg = solve_box_qp(qp, h, options, {}, x);
  out.force = contact_force(disc.finest_space(), a.full_vector(disc.problem(), x), scale);
  options.method = SolverMethod::kPdas;
  x.setZero();
  out.pdas = solve_box_qp(qp, h, options, {}, x);
  out.pdas_force = contact_force(disc.finest_space(), a.full_vector(disc.problem(), x), scale);
  return out;
}

}  // namespace fosls::testing
