#pragma once
// Case JSON → CaseSpec, with every problem reported at once (docs/case-format.md).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "case/case_error.hpp"
#include "case/case_spec.hpp"

namespace fosls {

/// Size limits that are part of validation.
struct CaseLimits {
  int max_refinements = 8;
  long long max_dofs = 6'000'000;         ///< DOFs of the finest level
  std::size_t max_text_bytes = 4u << 20;  ///< msh text
  std::size_t max_expression_length = 1024;
  std::size_t max_geometry_entities = 10000;
  std::size_t max_name_length = 200;
  /// The whole case JSON text (the CLI's case file; the service may use it as its body limit).
  std::size_t max_case_bytes = 16u << 20;
  /// Estimated triangles of the coarse mesh of a builtin or geometry mesh (≈ area / size²):
  /// keeps a tiny `mesh.size` from building a huge coarse mesh before the DOF limit is checked.
  long long max_coarse_triangles = 200'000;
  std::size_t max_path_length = 4096;  ///< mesh.geo_file
};

struct CaseReadOptions {
  CaseLimits limits;
  /// `mesh.geo_file` (a path to a gmsh .geo script) is accepted only from the command line:
  /// .geo scripts can run shell commands, so the service never allows them.
  bool allow_geo_file = false;
};

struct CaseReadResult {
  std::optional<CaseSpec> spec;  ///< set when errors is empty
  std::vector<CaseError> errors;
};

/// Reads and validates a parsed case JSON. Never throws for bad input.
CaseReadResult read_case(const nlohmann::json& j, const CaseReadOptions& options = {});

}  // namespace fosls
