#pragma once
// The result JSON of a solve (documented in docs/result-format.md, described field by field by
// result_rules.hpp), and the sentences that explain its warnings.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "assembly/fosls_assembler.hpp"
#include "case/format/case_spec.hpp"
#include "case/result/result_rules.hpp"
#include "case/result/result_warnings.hpp"
#include "post/contact_output.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

/// Sizes of the discrete problem that was solved.
struct ProblemSize {
  int levels = 0;
  long long dofs = 0;        ///< unknowns solved for
  long long dofs_total = 0;  ///< all DOFs of the finest level
  long long vertices = 0;
  long long cells = 0;  ///< triangles (2D) or tetrahedra (3D)
};

/// Wall-clock times of a run, in seconds.
struct RunTiming {
  double mesh_s = 0, assembly_s = 0, solve_s = 0, total_s = 0;
};

/// Peak resident set of the process (MiB) at the end of each stage of a run, so that a table
/// shows which stage set the peak (the solver's own stages are in SolverReport).
struct RunMemory {
  double mesh_mib = 0, assembly_mib = 0, hierarchy_mib = 0, peak_mib = 0;
};

StopReason stop_reason(const SolverReport& report);

/// The result's `contact` object of a 2D solve (a boundary of edges; 3D's is contact_faces.hpp's)
/// but for the constraint's direction and obstacles, which result_json adds.
nlohmann::json contact_json(const ContactResult& contact);

/// The whole result JSON of either dimension; `contact` is the dimension's contact object
/// (contact_json, face_contact_json).
nlohmann::json result_json(const CaseSpec& spec, const SolverReport& report, nlohmann::json contact,
                           const FunctionalParts& functional, const ProblemSize& size,
                           const RunTiming& timing, const RunMemory& memory);

}  // namespace fosls
