#include "solvers/subspace_acceleration.hpp"

#include <algorithm>
#include <cmath>

namespace fosls {

double SubspaceAcceleration::accelerate(const Vector& x_old, const Vector& r_old, Vector& x,
                                        Vector& r) {
  if (p_.size() != x.size()) return 0.0;
  // d = x − x_old and A d = r_old − r stay expressions: no vector of the problem's size is
  // allocated here (at 2M unknowns each is 16 MiB).
  const auto d = x - x_old;
  const auto ad = r_old - r;
  // J(x_old + a d + b p) is quadratic in (a, b) with Hessian H and gradient −g at (0, 0).
  const double hdd = d.dot(ad), hdp = d.dot(ap_), hpp = p_.dot(ap_);
  const double gd = d.dot(r_old), gp = p_.dot(r_old);
  const double det = hdd * hpp - hdp * hdp;
  // Nearly parallel directions: the 2×2 system carries no information beyond the step itself.
  // Written so that NaN (overflowing products, inf − inf) also leaves the step alone.
  if (!(hdd > 0 && hpp > 0) || !(det > 1e-10 * hdd * hpp)) return 0.0;
  const double a = (gd * hpp - gp * hdp) / det, b = (hdd * gp - hdp * gd) / det;
  if (!std::isfinite(a) || !std::isfinite(b)) return 0.0;
  // The move from x to the minimiser y: (a − 1) d + b p. J(y) ≤ J(x) since x is the point
  // (1, 0) of the same plane; along the segment from x to y, J stays ≤ J(x) (convexity), so
  // the largest feasible part of the segment is taken.
  // Both loops read d_i = x_i − x_old,i and (A d)_i = r_old,i − r_i before x_i and r_i change,
  // and compute the move and each DOF's limit the same way, so that the DOFs that set t are
  // recognised below and put exactly on their bound (x + t·m may miss it by an ulp, and a DOF
  // just inside its bound is not active for the next cycle's truncation).
  // The moves stay an expression, read per DOF before that DOF of x changes.
  const auto moves = (a - 1.0) * d + b * p_;
  auto limit = [&](int i, double m) {
    return step_to_bound(x[i], m, x[i] + m, qp_.lower[i], qp_.upper[i]);
  };
  const double t = max_feasible_step(x, moves, qp_.lower, qp_.upper);
  if (t == 0.0) return 0.0;
  for (int i = 0; i < x.size(); ++i) {
    const double m = moves[i];
    const double image = t * ((a - 1.0) * (r_old[i] - r[i]) + b * ap_[i]);
    const bool blocking = t < 1.0 && limit(i, m) <= t;
    const double bound = m > 0 ? qp_.upper[i] : qp_.lower[i];
    x[i] = blocking ? bound : std::clamp(x[i] + t * m, qp_.lower[i], qp_.upper[i]);
    r[i] -= image;
  }
  return t;
}

void SubspaceAcceleration::remember(const Vector& x_old, const Vector& r_old, const Vector& x,
                                    const Vector& r) {
  p_ = x - x_old;
  ap_ = r_old - r;
}

}  // namespace fosls
