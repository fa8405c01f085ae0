#include "case/case_admission.hpp"

#include <algorithm>
#include <array>

#include "case/early_group_check.hpp"
#include "case/memory_size.hpp"
#include "case/mesh_factory.hpp"
#include "case/solver_methods.hpp"
#include "case/time_estimate.hpp"
#include "mesh/coarse_mesh_estimate.hpp"
#include "mesh/geometry_checks.hpp"
#include "mesh/group_name_index.hpp"

namespace fosls {

namespace {

/// The geometry checks and size guards of a gmsh outline, as the case's problems.
std::vector<CaseError> outline_problems(const GmshOutline& outline, const MeshSpec& mesh,
                                        CoarseMeshEstimate& estimate) {
  std::vector<MeshProblem> problems = check_size_field(outline.size);
  for (auto& p : validate_geometry(outline.geometry)) problems.push_back(std::move(p));
  if (problems.empty()) {
    estimate = estimate_coarse_mesh(outline.geometry, outline.size);
    problems = check_coarse_mesh_estimate(estimate);
  }
  if (problems.empty()) return {};
  return to_case_exception(MeshError(std::move(problems)), mesh).errors();
}

/// Problems of the groups the case names against those the mesh has, and of a case the
/// Dirichlet groups do not hold.
std::vector<CaseError> group_problems(const CaseSpec& spec,
                                      const std::vector<std::string>& group_names) {
  std::vector<CaseError> errors;
  bool dirichlet = false;
  std::array<bool, 2> held = {false, false};  // some group prescribes u_x, u_y
  const GroupNameIndex known(group_names);
  for (const auto& [name, bc] : spec.boundary) {
    if (known.find(group_names, name) < 0)
      errors.push_back(unknown_group_problem(name, group_names));
    dirichlet |= bc.type == BoundaryCondition::Type::kDirichlet;
    for (int c = 0; c < 2; ++c)
      held[c] |= bc.type == BoundaryCondition::Type::kDirichlet && bc.prescribed[c];
  }
  if (!dirichlet) errors.push_back(no_dirichlet_problem());
  for (int c = 0; dirichlet && c < 2; ++c)
    if (!held[c])
      errors.push_back({"/boundary", std::string("no dirichlet group prescribes u_") + "xy"[c] +
                                         " (each has it null): the body can slide in that "
                                         "direction (frictionless contact cannot hold it) and "
                                         "the problem has no unique solution; prescribe u_" +
                                         "xy"[c] + " on at least one group"});
  return errors;
}

/// The size against the limits: unknowns against max_dofs, memory against max_memory_bytes,
/// time against max_seconds.
std::vector<CaseError> size_problems(const CaseSpec& spec, long long unknowns, bool exact,
                                     const CaseLimits& limits) {
  std::vector<CaseError> errors;
  // After meshing, a gmsh mesh is counted for the first time (its admission used an estimate).
  const std::string built =
      exact && gmsh_outline(spec.mesh) ? "counted on the coarse mesh gmsh built: " : "";
  if (spec.accuracy && spec.accuracy->max_dofs < kAccuracyLeastGrowth * unknowns)
    errors.push_back({"/accuracy/max_dofs",
                      std::to_string(spec.accuracy->max_dofs) +
                          " leaves no second level: the first (" +
                          std::to_string(spec.mesh.refinements) + " refinements) has " +
                          (exact ? "" : "about ") + std::to_string(unknowns) +
                          " DOFs and the next about 4 times as many, and the error estimate needs "
                          "two levels; raise accuracy.max_dofs or lower mesh.refinements"});
  if (unknowns > limits.max_dofs)
    errors.push_back(
        {"/mesh/refinements",
         built + std::to_string(spec.mesh.refinements) + " refinements of this mesh give " +
             (exact ? "" : "about ") + std::to_string(unknowns) + " unknowns" +
             (exact ? "" : " (estimated before meshing)") + ", more than the limit of " +
             std::to_string(limits.max_dofs) + "; use fewer refinements or a coarser mesh.size"});
  if (limits.max_memory_bytes > 0)
    if (auto e = check_memory_budget(admission_estimate(spec, unknowns, exact), spec.solver.method,
                                     limits.max_memory_bytes, limits.memory_budget_name)) {
      e->detail = built + e->detail;
      errors.push_back(std::move(*e));
    }
  if (auto e = check_time_budget(estimate_case_time(spec, unknowns), spec, unknowns,
                                 limits.max_seconds, limits.time_budget_name))
    errors.push_back(std::move(*e));
  return errors;
}

}  // namespace

ResourceEstimate admission_estimate(const CaseSpec& spec, long long unknowns, bool exact) {
  const int order = spec.mesh.order;
  ResourceEstimate estimate = estimate_resources(unknowns, exact, spec.solver.method, order);
  // An adaptive run may grow up to adaptivity.max_dofs: admit it for that size.
  if (spec.adaptivity && spec.adaptivity->steps > 0) {
    const ResourceEstimate adaptive =
        estimate_adaptive_resources(spec.adaptivity->max_dofs, spec.solver.method);
    if (adaptive.memory_bytes > estimate.memory_bytes) estimate = adaptive;
  }
  // The accuracy loop may refine up to its largest level below accuracy.max_dofs.
  if (spec.accuracy) {
    const long long largest = accuracy_largest_unknowns(unknowns, spec.accuracy->max_dofs);
    if (largest > unknowns) {
      estimate = estimate_resources(largest, false, spec.solver.method, order);
      estimate.limited_by = "/accuracy/max_dofs";
    }
  }
  return estimate;
}

std::vector<CaseError> check_against_groups(const CaseSpec& spec,
                                            const std::vector<std::string>& group_names,
                                            long long unknowns, bool unknowns_exact,
                                            const CaseLimits& limits) {
  std::vector<CaseError> errors = group_problems(spec, group_names);
  for (CaseError& e : size_problems(spec, unknowns, unknowns_exact, limits))
    errors.push_back(std::move(e));
  return errors;
}

CaseAdmission admit_case(const nlohmann::json& j, const CaseReadOptions& options) {
  CaseAdmission out;
  CaseReadResult read = read_case(j, options);
  if (!read.errors.empty()) {
    out.errors = std::move(read.errors);
    return out;
  }
  out.spec = std::move(read.spec);
  const CaseSpec& spec = *out.spec;
  std::vector<std::string> groups;
  long long unknowns = 0;
  bool exact = false;
  try {
    if (auto outline = gmsh_outline(spec.mesh)) {
      CoarseMeshEstimate coarse;
      out.errors = outline_problems(*outline, spec.mesh, coarse);
      if (!out.errors.empty()) return out;
      for (const auto& g : outline->geometry.groups) groups.push_back(g.name);
      unknowns = estimated_unknowns_after_refinement(coarse.triangles(), coarse.boundary_edges,
                                                     spec.mesh.refinements, spec.mesh.order);
    } else {
      const Mesh mesh = build_coarse_mesh(spec.mesh);  // square or msh: no gmsh
      groups = mesh.group_names();
      unknowns =
          unknowns_after_refinement(mesh.num_triangles(), mesh.num_edges(), mesh.num_vertices(),
                                    spec.mesh.refinements, spec.mesh.order);
      exact = true;
    }
  } catch (const CaseException& e) {
    out.errors = e.errors();
    return out;
  }
  out.estimate = admission_estimate(spec, unknowns, exact);
  out.time = estimate_case_time(spec, unknowns);
  out.errors = check_against_groups(spec, groups, unknowns, exact, options.limits);
  return out;
}

std::optional<CaseError> check_memory_budget(const ResourceEstimate& estimate, SolverMethod method,
                                             double budget_bytes, const std::string& budget_name) {
  if (estimate.memory_bytes <= budget_bytes) return std::nullopt;
  const bool adaptive = estimate.limited_by == "/adaptivity/max_dofs";
  const bool accuracy = estimate.limited_by == "/accuracy/max_dofs";
  std::string advice = adaptive   ? "lower adaptivity.max_dofs"
                       : accuracy ? "lower accuracy.max_dofs (the loop stops below it, without the "
                                    "accuracy if it needs more), or ask a larger accuracy.force"
                                  : "use fewer refinements or a coarser mesh.size";
  // Another method only if it converges on fine meshes (not pgs) and fits; the accuracy loop's
  // largest level is the thing to lower, whatever the method.
  for (const MethodInfo& m : solver_methods()) {
    if (accuracy || m.method == method || !converges_on_fine_meshes(m.method)) continue;
    if (estimate.order == 2 && m.method == SolverMethod::kTnnmg) continue;  // mmg or pdas only
    const ResourceEstimate other =
        adaptive ? estimate_adaptive_resources(estimate.unknowns, m.method)
                 : estimate_resources(estimate.unknowns, estimate.unknowns_exact, m.method,
                                      estimate.order);
    if (other.memory_bytes <= budget_bytes)
      advice += ", or solver.method " + std::string(m.name) + " (about " +
                format_bytes(other.memory_bytes) + ")";
  }
  return CaseError{estimate.limited_by, "the solve needs " + describe(estimate, method) +
                                            ", more than the " + format_bytes(budget_bytes) + " " +
                                            budget_name + "; " + advice};
}

}  // namespace fosls
