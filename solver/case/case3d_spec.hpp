#pragma once
// A 3D case ("dimension": 3) as the library sees it after its JSON has been validated
// (case3d_reader.hpp; docs/case-format.md, "3D cases"). Its own small format: the 2D case's
// material and solver sections, 3-vectors of numbers, a rigid plane, ball or gap function as the
// obstacle.

#include <array>
#include <functional>
#include <map>
#include <string>

#include "case/case_spec.hpp"
#include "mesh/tet_half_ball.hpp"

namespace fosls {

struct Mesh3dSpec {
  enum class Kind { kBox, kHalfBall, kMsh, kGeoFile };
  Kind kind = Kind::kBox;
  std::array<int, 3> cells = {2, 2, 2};  ///< box: cubes (six tetrahedra each) per direction
  Point3 lengths = Point3(1, 1, 1);      ///< box: [0, lx] × [0, ly] × [0, lz]
  HalfBallSpec ball;                     ///< half_ball
  std::string path;                      ///< msh_file, geo_file
  std::string msh_text;                  ///< msh (the text given, or msh_file's, read once)
  double size = 0.25;                    ///< geo_file: coarse edge length
  int refinements = 0;                   ///< levels = refinements + 1
};

/// The case field that gave the mesh: where a problem of the mesh source is reported.
inline std::string mesh3d_source_pointer(const Mesh3dSpec& m) {
  switch (m.kind) {
    case Mesh3dSpec::Kind::kMsh:
      return m.path.empty() ? "/mesh/msh" : "/mesh/msh_file";
    case Mesh3dSpec::Kind::kGeoFile:
      return "/mesh/geo_file";
    default:
      return "/mesh/builtin";
  }
}

/// A rigid obstacle of a 3D contact condition.
struct Obstacle3d {
  enum class Kind { kPlane, kSphere, kGap };
  Kind kind = Kind::kPlane;
  Point3 point = Point3::Zero();    ///< plane: a point of it
  Point3 normal = Point3::UnitZ();  ///< plane: unit normal from the plane into the body
  Point3 center = Point3::Zero();   ///< sphere: a rigid ball, the body outside it
  double radius = 1.0;              ///< sphere
  /// plane, sphere: a rigid translation from where point or center put it (a prescribed
  /// indentation, so the body can stay at rest).
  Point3 displacement = Point3::Zero();
  /// gap: g(x, y, z), the gap along the body normal itself (compiled once, when read).
  std::function<double(double, double, double)> gap;
  bool as_object =
      false;  ///< given as the field `obstacle` (errors point into it), not point/normal
  /// The distance from x to the obstacle along the body's unit outward normal n there: the
  /// first hit of the ray x + s n (+∞ when it misses); where x is already inside the ball, the
  /// distance back along n to its sphere (negative).
  double gap_along(const Point3& x, const Point3& n) const { return gap_from(x, n, displacement); }
  /// The same to the obstacle where the case puts it, before its displacement.
  double gap_at_rest(const Point3& x, const Point3& n) const {
    return gap_from(x, n, Point3::Zero());
  }
  /// "plane", "sphere" or "obstacle": the word for messages.
  const char* noun() const;

 private:
  /// The gap with the plane or sphere moved by `shift`.
  double gap_from(const Point3& x, const Point3& n, const Point3& shift) const;
};

/// A component of a 3D case's displacement or traction: a number or an expression of x, y, z.
using Component3d = std::function<double(double x, double y, double z)>;

struct Condition3d {
  enum class Type { kDirichlet, kNeumann, kPressure, kContact };
  Type type = Type::kNeumann;
  /// Displacement (Dirichlet) or traction (Neumann), compiled once when read; a Dirichlet
  /// component given as null is not prescribed (empty here, its bit clear in `prescribed`);
  /// pressure: p in values[0], the traction −p n with the face's outward normal.
  std::array<Component3d, 3> values;
  int prescribed = 7;   ///< Dirichlet: bit c when u_c is prescribed
  Obstacle3d obstacle;  ///< contact
  double gap_along(const Point3& x, const Point3& n) const { return obstacle.gap_along(x, n); }
};

struct Case3dSpec {
  std::string name = "case";
  Mesh3dSpec mesh;
  Material material;
  std::array<double, 3> body_force = {0, 0, 0};
  /// Condition per boundary group; groups not named are traction free.
  std::map<std::string, Condition3d> boundary;
  SolverOptions solver;
};

}  // namespace fosls
