#pragma once
// Declarative 2D geometry (points, straight segments, circular arcs, named boundary groups),
// meshed through the gmsh C++ API. No gmsh script text is ever involved.

#include <array>
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

}  // namespace fosls
