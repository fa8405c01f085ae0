#pragma once
// Declarative 2D geometry (points, straight segments, circular arcs, named boundary groups),
// meshed through the gmsh C++ API. No gmsh script text is ever involved.

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace fosls {

struct GeometrySpec {
  /// A boundary curve: a straight segment (points[0] → points[1]) or a circular arc
  /// (points[0] → points[1] around `center`, the shorter way; start and end equidistant from
  /// the centre).
  struct Curve {
    bool is_arc = false;
    std::array<int, 2> points = {-1, -1};
    int center = -1;  ///< index into `points`, arcs only
  };
  struct Group {
    std::string name;
    std::vector<int> curves;  ///< indices into `curves`
  };
  std::vector<Point> points;
  std::vector<Curve> curves;  ///< together they must form one closed loop
  std::vector<Group> groups;  ///< every curve in exactly one group
};

/// Target edge length of a mesh: `size` at `origin`, growing linearly with the distance to
/// `grading · size` at distance `reach` and beyond. grading = 1 is a uniform size. A
/// description rather than a function, so that it can be sent to the mesher process.
struct SizeField {
  double size = 0.25;
  double grading = 1.0;
  Point origin = Point::Zero();
  double reach = std::numeric_limits<double>::infinity();

  double at(const Point& x) const {
    if (grading == 1.0) return size;
    const double t = (x - origin).norm() / reach;
    return size * (1.0 + (grading - 1.0) * (t < 1.0 ? t : 1.0));
  }
};

}  // namespace fosls
