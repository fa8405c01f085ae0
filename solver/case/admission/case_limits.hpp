#pragma once
// Size limits that are part of validating a case, and the reader's options. The defaults are
// the documented limits (docs/case-format.md, "Limits", generated from case_limit_table());
// tests and programs may lower them. The coarse-mesh limits are the mesh layer's
// (mesh/coarse_mesh_estimate.hpp): they guard the mesher whoever calls it.

#include <cstddef>
#include <string>
#include <vector>

namespace fosls {

struct CaseLimits {
  int max_refinements = 8;
  /// A 3D case's: each refinement multiplies its unknowns by about 8.
  int max_refinements_3d = 5;
  /// DOFs of the finest level. 10 million: level 9 of the square (8.4M) fits, and mmg needs
  /// about 0.8 KB per unknown (docs/performance.md); whether a case fits the machine is the
  /// memory estimate's question (the service refuses what exceeds a job's budget).
  long long max_dofs = 10'000'000;
  std::size_t max_text_bytes = 4u << 20;  ///< msh text
  std::size_t max_expression_length = 1024;
  std::size_t max_geometry_entities = 10000;  ///< points, curves, groups, boundary conditions
  std::size_t max_name_length = 200;
  /// The whole case JSON text (the CLI's case file; the service may use it as its body limit).
  std::size_t max_case_bytes = 16u << 20;
  std::size_t max_path_length = 4096;  ///< mesh.geo_file, mesh.msh_file
  /// Memory one solve may use, in bytes; 0: not checked. A limit of the program that runs the
  /// case (the service's --max-job-memory, the CLI's --max-memory), not of the case format:
  /// a case whose memory estimate exceeds it is refused before meshing, and again with the
  /// exact unknowns once its coarse mesh is built (case/admission/case_admission.hpp).
  double max_memory_bytes = 0;
  /// What completes "more than the 2 GiB …" in messages: who sets the budget and for what.
  std::string memory_budget_name = "a solve may use";
  /// Wall-clock seconds a whole case may take; 0: not checked. The service's --max-job-seconds
  /// (the CLI sets none): a case whose time estimate (case/admission/job_time.hpp) exceeds it is
  /// refused before meshing.
  double max_seconds = 0;
  /// What completes "more than the 1 h …" in messages.
  std::string time_budget_name = "a run may take";
};

/// What a reader accepts: the limits, and whether a case may name local files.
struct CaseReadOptions {
  CaseLimits limits;
  /// Paths of local files (`mesh.geo_file`, `mesh.msh_file`) are accepted only from the
  /// command line: the service never reads files named by a request, and .geo scripts can run
  /// shell commands.
  bool allow_local_files = false;
};

/// One limit as the documentation lists it.
struct CaseLimitRow {
  std::string what;   ///< e.g. "msh text"
  std::string value;  ///< e.g. "4 MiB"
};

/// Every limit of `limits`, in words, for docs/case-format.md.
std::vector<CaseLimitRow> case_limit_table(const CaseLimits& limits = {});

}  // namespace fosls
