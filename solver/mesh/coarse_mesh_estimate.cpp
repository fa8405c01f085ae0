#include "mesh/coarse_mesh_estimate.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/geometry_checks.hpp"
#include "mesh/plane_geometry.hpp"

namespace fosls {

namespace {

using plane::angle_of;
using plane::cross;
using plane::kPi;
using plane::num;
using plane::wrap;

const std::string kSizeField = "/size";

/// One curve of the boundary loop as a polyline from its start to just before its end (arcs
/// in 16 straight pieces), and the fewest segments gmsh gives it.
struct CurvePiece {
  std::vector<Point> points;
  Point end;
  int minimum_segments = 1;
};

/// gmsh's minimum for a curve (gmshEdge::minimumMeshSegments): one segment for a line, and
/// (Mesh.MinimumCircleNodes − 1) · angle / 2π, rounded up, for an arc (7 nodes by default).
int minimum_segments(double arc_angle) {
  constexpr int kMinimumCircleNodes = 7;
  return std::max(1, static_cast<int>(0.99 + (kMinimumCircleNodes - 1) * arc_angle / (2 * kPi)));
}

std::vector<CurvePiece> curve_pieces(const GeometrySpec& g, const std::vector<int>& loop) {
  std::vector<CurvePiece> pieces;
  for (int signed_tag : loop) {
    const auto& cv = g.curves[std::abs(signed_tag) - 1];
    Point a = g.points[cv.points[0]], b = g.points[cv.points[1]];
    if (signed_tag < 0) std::swap(a, b);
    CurvePiece piece;
    piece.end = b;
    if (!cv.is_arc) {
      piece.points.push_back(a);
      pieces.push_back(std::move(piece));
      continue;
    }
    const Point c = g.points[cv.center];
    const double r = (a - c).norm();
    double t0 = angle_of(a - c), sweep = wrap(angle_of(b - c) - t0);
    if (sweep > kPi) sweep -= 2 * kPi;
    constexpr int kPieces = 16;
    for (int i = 0; i < kPieces; ++i) {
      double t = t0 + sweep * i / kPieces;
      piece.points.push_back(c + r * Point(std::cos(t), std::sin(t)));
    }
    piece.minimum_segments = minimum_segments(std::abs(sweep));
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

/// The boundary loop as one polygon.
std::vector<Point> polygon(const std::vector<CurvePiece>& pieces) {
  std::vector<Point> poly;
  for (const CurvePiece& piece : pieces)
    poly.insert(poly.end(), piece.points.begin(), piece.points.end());
  return poly;
}

double polygon_area(const std::vector<Point>& poly) {
  double area = 0.0;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    area += 0.5 * cross(poly[j], poly[i]);
  return std::abs(area);
}

bool inside(const std::vector<Point>& poly, const Point& x) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Point &a = poly[i], &b = poly[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < a.x() + (x.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      in = !in;
  }
  return in;
}

/// ∫ 1 / (√3/4 h²) over the polygon, sampled on a 64 × 64 grid over its bounding box.
double area_triangles(const std::vector<Point>& poly, const SizeField& size) {
  Eigen::Vector2d lo = poly[0], hi = poly[0];
  for (const Point& p : poly) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  constexpr int kSamples = 64;
  const Eigen::Vector2d cell = (hi - lo) / kSamples;
  const double cell_area = cell.x() * cell.y();
  double count = 0.0;
  bool any = false;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const Point x = lo + Eigen::Vector2d((i + 0.5) * cell.x(), (j + 0.5) * cell.y());
      if (!inside(poly, x)) continue;
      any = true;
      const double h = size.at(x);
      count += cell_area / (std::sqrt(3.0) / 4 * h * h);
    }
  if (!any) {  // thinner than a sample cell: fall back to the size at the first point
    const double h = size.at(poly[0]);
    count = polygon_area(poly) / (std::sqrt(3.0) / 4 * h * h);
  }
  return count;
}

/// ∫ 1 / h along a straight side, sampled at 64 midpoints.
double edges_along(const Point& a, const Point& b, const SizeField& size) {
  const Point d = b - a;
  double count = 0.0;
  constexpr int kPieces = 64;
  for (int k = 0; k < kPieces; ++k)
    count += d.norm() / kPieces / size.at(a + (k + 0.5) / kPieces * d);
  return count;
}

}  // namespace

std::vector<MeshProblem> check_size_field(const SizeField& size) {
  std::vector<MeshProblem> problems;
  if (!(size.size > 0) || !std::isfinite(size.size))
    problems.push_back({kSizeField, "the mesh size must be a positive number"});
  if (!(size.grading >= 1) || !std::isfinite(size.grading))
    problems.push_back({kSizeField, "the grading of the mesh size must be a number of at least 1"});
  if (!(size.reach > 0) || !size.origin.allFinite())
    problems.push_back({kSizeField, "the graded mesh size needs a finite origin and a reach > 0"});
  return problems;
}

CoarseMeshEstimate estimate_coarse_mesh(const GeometrySpec& geometry, const SizeField& size) {
  const std::vector<CurvePiece> pieces = curve_pieces(geometry, walk_loop(geometry));
  const std::vector<Point> poly = polygon(pieces);
  CoarseMeshEstimate estimate;
  estimate.area_triangles = area_triangles(poly, size);
  double along = 0.0, excess = 0.0, perimeter = 0.0;
  for (const CurvePiece& piece : pieces) {
    double curve = 0.0;
    for (std::size_t i = 0; i < piece.points.size(); ++i) {
      const Point& b = i + 1 < piece.points.size() ? piece.points[i + 1] : piece.end;
      curve += edges_along(piece.points[i], b, size);
      perimeter += (b - piece.points[i]).norm();
    }
    // gmsh's count of segments: max(minimum, int(∫ 1/h + 0.99)).
    const double segments = std::max<double>(piece.minimum_segments, std::floor(curve + 0.99));
    along += curve;
    excess += segments - curve;
    estimate.boundary_edges += segments;
  }
  // The band one mean boundary size wide along the boundary, as a share of the area.
  const double mean_size = along > 0 ? perimeter / along : 0.0;
  const double room =
      mean_size > 0 ? std::min(1.0, polygon_area(poly) / (perimeter * mean_size)) : 0.0;
  estimate.grading_triangles = kGradingTrianglesPerExcessEdge * room * excess;
  return estimate;
}

std::vector<MeshProblem> check_coarse_mesh_estimate(const CoarseMeshEstimate& estimate) {
  if (estimate.boundary_edges > kMaxCoarseBoundaryEdges)
    return {{kSizeField,
             "the mesh size is too large for how thin this geometry is, or too small "
             "for its boundary: about " +
                 num(estimate.boundary_edges) + " coarse boundary edges (at most " +
                 num(kMaxCoarseBoundaryEdges) +
                 "); use a size near the thickness of the thinnest part, or a "
                 "geometry less long and thin"}};
  if (estimate.triangles() > kMaxCoarseTriangles)
    return {{kSizeField, "the mesh size is too small for this geometry: about " +
                             num(estimate.triangles()) + " coarse triangles (at most " +
                             num(kMaxCoarseTriangles) +
                             "); use a larger size and refinements instead"}};
  return {};
}

}  // namespace fosls
