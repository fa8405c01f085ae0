#pragma once
// How large the coarse mesh of a declarative geometry will be, estimated before anything is
// meshed, so that sizes that would let the mesher run for minutes or exhaust memory are
// refused up front.

#include <vector>

#include "mesh/geometry_spec.hpp"
#include "mesh/mesh_error.hpp"

namespace fosls {

/// Estimated coarse triangles above which meshing is refused: use a larger size and
/// refinements instead.
inline constexpr double kMaxCoarseTriangles = 250000;

/// Estimated coarse boundary edges above which meshing is refused. Within the triangle limit a
/// mesh has this many boundary edges only when the domain is very long and thin (aspect ratio
/// beyond ~400) or much thinner than the mesh size, and there gmsh's 2D Delaunay is slow and
/// fragile: minutes and aborts beyond a few times this limit (docs/performance.md, "Measurements
/// behind choices in the code").
inline constexpr double kMaxCoarseBoundaryEdges = 10000;

/// Estimated counts of the coarse mesh for a size field.
///
/// gmsh meshes each curve on its own, with at least one segment (at least a part of
/// Mesh.MinimumCircleNodes for an arc), so boundary edges are counted curve by curve: a
/// polygon of 10 000 sides a thousand times shorter than the size has 10 000 boundary edges,
/// not the 6 its perimeter over the size gives. A triangulated disk has T = B − 2 + 2 V_inner
/// triangles; the inner vertices are those of the area at the size, plus those of the layers in
/// which the mesh grows from boundary edges shorter than the size to the size. That growth
/// needs room: it is counted in proportion to how much of a band one size wide along the
/// boundary the domain has (none for a thin zig-zag whose vertices are all on its boundary).
/// Fitted on polygons and stars of 100 to 10 000 sides and on the geometry cases of the tests
/// (docs/case-format.md, "Resources").
struct CoarseMeshEstimate {
  double area_triangles = 0;  ///< ∫ 1 / (√3/4 h²) over the domain: triangles of good shape
  double boundary_edges = 0;  ///< Σ over curves of max(its minimum, ⌈∫ 1/h along it⌉)
  /// Triangles of the layers grading from boundary edges shorter than the size up to it.
  double grading_triangles = 0;
  /// The triangles the mesher makes: at least one per boundary edge, however thin the domain.
  double triangles() const { return area_triangles + boundary_edges + grading_triangles; }
};

/// Triangles of the grading layers per boundary edge in excess of ∫ 1/h (a curve shorter than
/// the size still gets one edge) where the domain has room for them.
inline constexpr double kGradingTrianglesPerExcessEdge = 0.6;

/// Problems of a size field itself (at /size): a non-positive or non-finite size, a grading
/// below 1, a non-positive reach.
std::vector<MeshProblem> check_size_field(const SizeField& size);

/// Estimates the coarse mesh of a geometry that validate_geometry accepted.
CoarseMeshEstimate estimate_coarse_mesh(const GeometrySpec& geometry, const SizeField& size);

/// The problem (at /size) with an estimate beyond the limits, if any.
std::vector<MeshProblem> check_coarse_mesh_estimate(const CoarseMeshEstimate& estimate);

}  // namespace fosls
