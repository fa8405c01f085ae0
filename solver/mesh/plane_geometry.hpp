#pragma once
// Small formulas of plane geometry and the number format of geometry messages, shared by the
// geometry checks and the coarse mesh estimate.

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "mesh/mesh.hpp"

namespace fosls::plane {

inline constexpr double kPi = std::numbers::pi;

/// z component of the cross product of two plane vectors.
inline double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Angle of v in [0, 2π).
inline double angle_of(const Point& v) {
  const double a = std::atan2(v.y(), v.x());
  return a < 0 ? a + 2 * kPi : a;
}

/// Wraps x into [0, 2π).
inline double wrap(double x) {
  x = std::fmod(x, 2 * kPi);
  return x < 0 ? x + 2 * kPi : x;
}

/// A number with 6 significant digits, for messages.
inline std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

/// "(x, y)" for messages.
inline std::string where(const Point& p) { return "(" + num(p.x()) + ", " + num(p.y()) + ")"; }

}  // namespace fosls::plane
