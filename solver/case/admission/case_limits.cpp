#include "case/admission/case_limits.hpp"

#include "mesh/coarse_mesh_estimate.hpp"

namespace fosls {

namespace {

/// 4194304 → "4 MiB", 1024 → "1024".
std::string bytes_text(std::size_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

/// 6000000 → "6 000 000".
std::string grouped(long long n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

}  // namespace

std::vector<CaseLimitRow> case_limit_table(const CaseLimits& l) {
  return {
      {"case JSON text", bytes_text(l.max_case_bytes)},
      {"`mesh.msh` text", bytes_text(l.max_text_bytes)},
      {"names (case, boundary groups, geometry groups)",
       std::to_string(l.max_name_length) + " characters"},
      {"expressions", std::to_string(l.max_expression_length) + " characters"},
      {"`mesh.geo_file` path", std::to_string(l.max_path_length) + " characters"},
      {"geometry points, curves and groups; boundary conditions",
       grouped(static_cast<long long>(l.max_geometry_entities)) + " each"},
      {"`mesh.refinements`", "at most " + std::to_string(l.max_refinements) + " (2D), " +
                                 std::to_string(l.max_refinements_3d) + " (3D)"},
      {"estimated coarse triangles (builtin and geometry meshes)",
       grouped(static_cast<long long>(kMaxCoarseTriangles))},
      {"estimated coarse boundary edges (geometry meshes)",
       grouped(static_cast<long long>(kMaxCoarseBoundaryEdges))},
      {"unknowns on the finest level (estimated before meshing, counted again once the coarse "
       "mesh is built)",
       grouped(l.max_dofs)},
  };
}

}  // namespace fosls
