#pragma once
// The friction law on the discrete contact edges (docs/method.md §8), shared by the assembly,
// which lays it out, and the solvers, which update Coulomb's bounds from the iterate. On a
// frictional edge e the slip bound s̄_e (Tresca's ∫_e s/μ, Coulomb's 𝔣 max(0, −S_n)) bounds S_t
// by ±s̄_e and weighs the kinks of the slip at the edge's end points by C3 s̄_e/2 each (the
// trapezoidal rule of C3 ∫_e s |Δu_t|/μ).

#include <array>
#include <functional>
#include <vector>

#include "core/box_qp.hpp"
#include "core/kinks.hpp"

namespace fosls {

/// A frictional contact edge in the QP.
struct FrictionEdge {
  int edge = -1;
  int st = -1;  ///< free index of S_t
  int sn = -1;  ///< free index of S_n
  /// Per end point: the kink index (a free U_t), or -1 with `fixed_slip` the slip of a fixed one.
  std::array<int, 2> kink = {-1, -1};
  std::array<double, 2> fixed_slip = {0.0, 0.0};
  double tresca = 0.0;       ///< s̄_e of a Tresca bound
  double coefficient = 0.0;  ///< 𝔣 of Coulomb friction (0: Tresca)
};

struct FrictionLayout {
  std::vector<FrictionEdge> edges;
  double c3 = 0.0;
  bool empty() const { return edges.empty(); }
  bool coulomb() const;
};

/// s̄_e of edge f at x (free DOFs; S_n read for Coulomb).
double slip_bound(const FrictionEdge& f, const Vector& x);

/// The kink weights C3 Σ_{e ∋ v} s̄_e/2 for the slip bounds `bounds` (one per edge of the
/// layout) in kinks.weight, and the kinks' value at fixed slips in kinks.constant.
void set_kink_weights(const FrictionLayout& layout, const std::vector<double>& bounds,
                      Kinks& kinks);

/// Which bounds to set, from those set before (`s`) and the slip bounds at x (`g`); `first`:
/// none was set before. Without one, g.
using BoundChoice = std::function<Vector(const Vector& s, const Vector& g, bool first)>;

/// Sets ±s̄_e on S_t in `qp` and the kink weights for the slip bounds at x (or what `choose`
/// makes of them). Returns the largest change of an s̄_e at x from the bound set before,
/// relative to the largest s̄_e (1 the first time).
double set_friction_bounds(const FrictionLayout& layout, const Vector& x, BoxQp& qp, Kinks& kinks,
                           const BoundChoice& choose = {});

/// The friction term C3 Σ_e S_t (ΔU_t,p + ΔU_t,q)/2 + the kinks at the free DOFs x.
double friction_functional(const FrictionLayout& layout, const Kinks& kinks, const Vector& x);

}  // namespace fosls
