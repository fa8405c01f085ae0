#pragma once
// Runs a 3D case (case3d_spec.hpp): the tetrahedral mesh and its uniform refinements, the
// P1³ × RT0³ discretisation, the solve by mmg or pdas, and the result JSON
// (docs/result-format.md, "3D results").

#include <atomic>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "case/case3d_spec.hpp"
#include "case/case_limits.hpp"
#include "solvers/iteration_record.hpp"

namespace fosls {

struct Run3dControl {
  bool want_vtu = false;
  bool vtu_ascii = false;
  std::function<void(const IterationRecord&)> on_iteration;
  /// When set and true, the solve stops at its next iteration and the output says cancelled.
  const std::atomic<bool>* cancel = nullptr;
};

struct Run3dOutput {
  bool cancelled = false;  ///< stopped by Run3dControl::cancel: no result, no VTU
  nlohmann::json result;
  std::string vtu;  ///< with want_vtu
};

/// Throws CaseException for a problem only the mesh shows (an unknown group, a contact face
/// that does not face the plane, too many unknowns, a mesh source that fails).
Run3dOutput run_case_3d(const Case3dSpec& spec, const Run3dControl& control = {},
                        const CaseLimits& limits = {});

}  // namespace fosls
