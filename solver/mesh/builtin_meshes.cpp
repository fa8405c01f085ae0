#include "mesh/builtin_meshes.hpp"

#include <cmath>
#include <stdexcept>

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

}  // namespace fosls
