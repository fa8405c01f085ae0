#include "mesh/builtin_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mesh/geometry_spec.hpp"
#include "mesh/gmsh_mesh.hpp"

namespace fosls {

Mesh make_square(const SquareParams& p) {
  if (!(p.width > 0 && p.height > 0 && p.size > 0))
    throw std::invalid_argument("square: width, height and size must be positive");
  const int nx = std::max(1, static_cast<int>(std::ceil(p.width / p.size - 1e-9)));
  const int ny = std::max(1, static_cast<int>(std::ceil(p.height / p.size - 1e-9)));
  std::vector<Point> v;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) v.emplace_back(p.x0 + p.width * i / nx, p.y0 + p.height * j / ny);
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      tris.push_back({a, b, c});
      tris.push_back({a, c, d});
    }
  std::vector<BoundarySegment> seg;
  for (int i = 0; i < nx; ++i) {
    seg.push_back({id(i, 0), id(i + 1, 0), 0, -1});
    seg.push_back({id(i, ny), id(i + 1, ny), 2, -1});
  }
  for (int j = 0; j < ny; ++j) {
    seg.push_back({id(nx, j), id(nx, j + 1), 1, -1});
    seg.push_back({id(0, j), id(0, j + 1), 3, -1});
  }
  return Mesh(std::move(v), std::move(tris), std::move(seg), {"bottom", "right", "top", "left"});
}

GmshOutline hertz_outline(const HertzParams& p) {
  if (!(p.radius > 0) || !std::isfinite(p.radius))
    throw std::invalid_argument("hertz: radius must be a positive number");
  if (!(p.contact_fraction > 0 && p.contact_fraction < 1))
    throw std::invalid_argument("hertz: contact_fraction must lie strictly between 0 and 1");
  if (!(p.size > 0) || !std::isfinite(p.size))
    throw std::invalid_argument("hertz: size must be a positive number");
  if (!(p.grading >= 1) || !std::isfinite(p.grading))
    throw std::invalid_argument("hertz: grading must be a number of at least 1");
  const double r = p.radius;
  const double xc = p.contact_fraction * r;
  const double yc = r - std::sqrt(r * r - xc * xc);
  GeometrySpec g;
  // 0: centre, 1: contact point, 2/5: ends of the contact group, 3/4: corners of the flat side.
  g.points = {Point(0, r), Point(0, 0), Point(xc, yc), Point(r, r), Point(-r, r), Point(-xc, yc)};
  g.curves = {{true, {1, 2}, 0},
              {true, {2, 3}, 0},
              {false, {3, 4}, -1},
              {true, {4, 5}, 0},
              {true, {5, 1}, 0}};
  g.groups = {{"top", {2}}, {"contact", {0, 4}}, {"free", {1, 3}}};
  // Edge length grows linearly with the distance from the contact point, from size at the
  // origin to grading * size at the corners of the flat side (distance √2 R).
  SizeField size;
  size.size = p.size;
  size.grading = p.grading;
  size.origin = Point(0, 0);
  size.reach = std::sqrt(2.0) * r;
  return {std::move(g), size};
}

Mesh make_hertz(const HertzParams& p, const MeshingControl& control) {
  const GmshOutline outline = hertz_outline(p);
  return mesh_from_geometry(outline.geometry, outline.size, control);
}

}  // namespace fosls
