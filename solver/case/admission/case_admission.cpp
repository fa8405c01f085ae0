#include "case/admission/case_admission.hpp"

#include <algorithm>
#include <array>

#include "case/admission/early_group_check.hpp"
#include "case/admission/memory_size.hpp"
#include "case/admission/time_estimate.hpp"
#include "case/format/solver_methods.hpp"
#include "case/run/mesh_factory.hpp"
#include "case/run/volume_mesh_checks.hpp"
#include "mesh/coarse_mesh_estimate.hpp"
#include "mesh/geometry_checks.hpp"
#include "mesh/group_name_index.hpp"
#include "strategy/force_accuracy.hpp"

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

/// Problems of the groups the case names against those the mesh has (when known), and of a
/// case the Dirichlet groups do not hold.
std::vector<CaseError> group_problems(const CaseSpec& spec,
                                      const std::optional<std::vector<std::string>>& group_names) {
  std::vector<CaseError> errors;
  bool dirichlet = false;
  std::array<bool, 3> held = {false, false, false};  // some group prescribes u_x, u_y, u_z
  const GroupNameIndex known(group_names ? *group_names : std::vector<std::string>{});
  for (const auto& [name, bc] : spec.boundary) {
    if (group_names && known.find(*group_names, name) < 0)
      errors.push_back(unknown_group_problem(name, *group_names));
    dirichlet |= bc.type == BoundaryCondition::Type::kDirichlet;
    for (int c = 0; c < 3; ++c)
      held[c] |= bc.type == BoundaryCondition::Type::kDirichlet && bc.prescribed[c];
  }
  if (!dirichlet) errors.push_back(no_dirichlet_problem());
  for (int c = 0; dirichlet && c < spec.dimension; ++c)
    if (!held[c])
      errors.push_back({"/boundary", std::string("no dirichlet group prescribes u_") + "xyz"[c] +
                                         " (each has it null): the body can slide in that "
                                         "direction (frictionless contact cannot hold it) and "
                                         "the problem has no unique solution; prescribe u_" +
                                         "xyz"[c] + " on at least one group"});
  return errors;
}

/// What admission knows of a 2D case's mesh without gmsh: a geometry's or the hertz outline's
/// estimate, or the square's or msh text's mesh built.
struct Mesh2dCount {
  std::vector<CaseError> errors;
  std::vector<std::string> groups;
  ProblemCount count;
};

Mesh2dCount count_2d_mesh(const CaseSpec& spec) {
  Mesh2dCount out;
  const MeshSpec& m = spec.mesh;
  out.count.order = m.order;
  if (auto outline = gmsh_outline(m)) {
    CoarseMeshEstimate coarse;
    out.errors = outline_problems(*outline, m, coarse);
    if (!out.errors.empty()) return out;
    for (const auto& g : outline->geometry.groups) out.groups.push_back(g.name);
    out.count.unknowns = estimated_unknowns_after_refinement(
        coarse.triangles(), coarse.boundary_edges, m.refinements, m.order);
    out.count.coarse_unknowns =
        estimated_unknowns_after_refinement(coarse.triangles(), coarse.boundary_edges, 0);
    return out;
  }
  const Mesh mesh = build_coarse_mesh(m);  // square or msh: no gmsh
  out.groups = mesh.group_names();
  out.count = {
      unknowns_after_refinement(mesh.num_triangles(), mesh.num_edges(), mesh.num_vertices(),
                                m.refinements, m.order),
      unknowns_after_refinement(mesh.num_triangles(), mesh.num_edges(), mesh.num_vertices(), 0),
      true, m.order, 2};
  return out;
}

/// What makes a mesh coarser: its size in 2D, its cells or its file in 3D.
std::string coarser(const CaseSpec& spec) { return spec.dimension == 3 ? "mesh" : "mesh.size"; }

}  // namespace

std::vector<CaseError> check_size(const CaseSpec& spec, const ProblemCount& count,
                                  const CaseLimits& limits) {
  std::vector<CaseError> errors;
  const long long unknowns = count.unknowns;
  const bool exact = count.exact;
  // After meshing, a gmsh mesh is counted for the first time (its admission used an estimate).
  const bool from_gmsh = spec.dimension == 3 ? spec.mesh.kind == MeshSpec::Kind::kGeoFile
                                             : gmsh_outline(spec.mesh).has_value();
  const std::string built = exact && from_gmsh ? "counted on the coarse mesh gmsh built: " : "";
  // Uniform levels grow by 2.8–4; an adaptive estimate needs a level with kAdaptiveSpan times
  // the first's unknowns (force_accuracy.hpp).
  const bool adaptive = spec.accuracy && spec.accuracy->adaptive;
  if (spec.accuracy &&
      spec.accuracy->max_dofs < (adaptive ? kAdaptiveSpan : kAccuracyLeastGrowth) * unknowns)
    errors.push_back({"/accuracy/max_dofs",
                      std::to_string(spec.accuracy->max_dofs) +
                          " leaves no second level: the first (" +
                          std::to_string(spec.mesh.refinements) + " refinements) has " +
                          (exact ? "" : "about ") + std::to_string(unknowns) + " DOFs and " +
                          (adaptive ? "the error estimate needs a level with twice as many"
                                    : "the next about 4 times as many, and the error estimate "
                                      "needs two levels") +
                          "; raise accuracy.max_dofs or lower mesh.refinements"});
  if (unknowns > limits.max_dofs)
    errors.push_back(
        {"/mesh/refinements", built + std::to_string(spec.mesh.refinements) +
                                  " refinements of this mesh give " + (exact ? "" : "about ") +
                                  std::to_string(unknowns) + " unknowns" +
                                  (exact ? "" : " (estimated before meshing)") +
                                  ", more than the limit of " + std::to_string(limits.max_dofs) +
                                  "; use fewer refinements or a coarser " + coarser(spec)});
  if (limits.max_memory_bytes > 0)
    if (auto e = check_memory_budget(admission_estimate(spec, count), spec, limits.max_memory_bytes,
                                     limits.memory_budget_name)) {
      e->detail = built + e->detail;
      errors.push_back(std::move(*e));
    }
  if (auto e = check_time_budget(estimate_case_time(spec, count), spec, count, limits.max_seconds,
                                 limits.time_budget_name))
    errors.push_back(std::move(*e));
  return errors;
}

ResourceEstimate admission_estimate(const CaseSpec& spec, const ProblemCount& counted) {
  // Coulomb with mmg may fall back to pdas (solvers/coulomb_fallback.hpp): the estimate prices it.
  ProblemCount count = counted;
  count.coulomb = std::any_of(spec.boundary.begin(), spec.boundary.end(), [](const auto& b) {
    return b.second.type == BoundaryCondition::Type::kContact &&
           b.second.friction_coefficient > 0.0;
  });
  ResourceEstimate estimate = estimate_resources(count, spec.solver.method);
  // An adaptive run may grow up to adaptivity.max_dofs: admit it for that size.
  if (spec.adaptivity && spec.adaptivity->steps > 0) {
    const ResourceEstimate adaptive =
        estimate_adaptive_resources(spec.adaptivity->max_dofs, count, spec.solver.method);
    if (adaptive.memory_bytes > estimate.memory_bytes) estimate = adaptive;
  }
  // An adaptive accuracy loop bisects up to accuracy.max_dofs, with adaptivity's hierarchy.
  if (spec.accuracy && spec.accuracy->adaptive) {
    estimate = estimate_adaptive_resources(spec.accuracy->max_dofs, count, spec.solver.method);
    estimate.limited_by = "/accuracy/max_dofs";
    return estimate;
  }
  // A uniform one may refine up to its largest level below accuracy.max_dofs.
  if (spec.accuracy) {
    const long long largest = accuracy_largest_unknowns(count.unknowns, spec.accuracy->max_dofs);
    if (largest > count.unknowns) {
      ProblemCount at_largest = count;
      at_largest.unknowns = largest;
      at_largest.exact = false;
      estimate = estimate_resources(at_largest, spec.solver.method);
      estimate.limited_by = "/accuracy/max_dofs";
    }
  }
  return estimate;
}

std::vector<CaseError> check_against_groups(
    const CaseSpec& spec, const std::optional<std::vector<std::string>>& group_names,
    const ProblemCount& count, const CaseLimits& limits) {
  std::vector<CaseError> errors = group_problems(spec, group_names);
  for (CaseError& e : check_size(spec, count, limits)) errors.push_back(std::move(e));
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
  std::optional<std::vector<std::string>> groups;
  std::optional<ProblemCount> count;
  try {
    if (spec.dimension == 3) {
      // A 3D builtin is counted from its cells, an msh text's mesh read and its groups
      // checked; a geo_file is counted once gmsh has meshed it (by the runner).
      Mesh3dCount counted = count_3d_mesh(spec);
      out.errors = std::move(counted.errors);
      count = counted.count;
    } else {
      Mesh2dCount counted = count_2d_mesh(spec);
      out.errors = std::move(counted.errors);
      groups = std::move(counted.groups);
      count = counted.count;
    }
  } catch (const CaseException& e) {
    out.errors = e.errors();
    return out;
  }
  if (!out.errors.empty()) return out;
  if (!count) {
    out.errors = group_problems(spec, groups);
    return out;
  }
  out.estimate = admission_estimate(spec, *count);
  out.time = estimate_case_time(spec, *count);
  out.errors = check_against_groups(spec, groups, *count, options.limits);
  return out;
}

std::optional<CaseError> check_memory_budget(const ResourceEstimate& estimate, const CaseSpec& spec,
                                             double budget_bytes, const std::string& budget_name) {
  if (estimate.memory_bytes <= budget_bytes) return std::nullopt;
  const SolverMethod method = spec.solver.method;
  const bool adaptive = estimate.limited_by == "/adaptivity/max_dofs";
  const bool accuracy = estimate.limited_by == "/accuracy/max_dofs";
  std::string advice = adaptive   ? "lower adaptivity.max_dofs"
                       : accuracy ? "lower accuracy.max_dofs (the loop stops below it, without the "
                                    "accuracy if it needs more), or ask a larger accuracy.force"
                       : estimate.dimension == 3 ? "use fewer refinements or a coarser mesh"
                                                 : "use fewer refinements or a coarser mesh.size";
  // Another method only if it converges on fine meshes (not pgs), solves this case and fits; the
  // accuracy loop's largest level is the thing to lower, whatever the method.
  for (const MethodInfo& m : solver_methods()) {
    if (accuracy || m.method == method || !converges_on_fine_meshes(m.method) ||
        !method_solves(m.method, spec))
      continue;
    const ResourceEstimate other =
        adaptive ? estimate_adaptive_resources(estimate.unknowns, estimate.count(), m.method)
                 : estimate_resources(estimate.count(), m.method);
    if (other.memory_bytes <= budget_bytes)
      advice += ", or solver.method " + std::string(m.name) + " (about " +
                format_bytes(other.memory_bytes) + ")";
  }
  return CaseError{estimate.limited_by, "the solve needs " + describe(estimate, method) +
                                            ", more than the " + format_bytes(budget_bytes) + " " +
                                            budget_name + "; " + advice};
}

}  // namespace fosls
