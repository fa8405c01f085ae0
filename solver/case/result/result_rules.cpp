// The result JSON described field by field, as the case is (case_rules.hpp): the source of
// docs/result-format.md's tables and of the result's JSON Schema, and the check that every
// field a solve emits is documented (tests/unit/result_format_test.cpp).

#include "case/result/result_rules.hpp"

#include "case/format/solver_methods.hpp"
#include "case/result/result_rule_parts.hpp"
#include "case/result/result_warnings.hpp"

namespace fosls {

namespace result_parts {

ValueRule count() { return integer_value(Range::non_negative()); }
ValueRule number() { return number_value(); }
ValueRule numbers(std::string what) { return list_value(number_value(), std::move(what)); }
ValueRule text() { return string_value(static_cast<std::size_t>(-1) >> 1, "the text"); }
ValueRule number_or_null() {
  return one_of_value({number_value(), null_value()}, "a number or null");
}
ValueRule converged_by_value() {
  return choice_value({"kkt_residual", "algebraic_error", "rounding_level", "none"});
}

ObjectRulePtr object_rule(std::string title, std::string anchor, std::vector<FieldRule> fields) {
  auto r = std::make_shared<ObjectRule>();
  r->title = std::move(title);
  r->anchor = std::move(anchor);
  r->fields = std::move(fields);
  return r;
}

ObjectRulePtr history_rule() {
  return object_rule(
      "an iteration", "iteration",
      {output_field("iteration", count(), "1", "0 for the initial iterate, then 1, 2, ..."),
       output_field("energy", number(), "scaled",
                    "the functional J(x_k) = ½xᵀAx − bᵀx + c (not a physical energy)"),
       output_field("correction", number(), "scaled", "energy norm of the step ‖x_k − x_{k−1}‖_A"),
       output_field("kkt_residual", number(), "scaled",
                    "‖x − P_K(x − (Ax − b))‖₂, the quantity of the stopping rule"),
       output_field("active", count(), "1", "bounded unknowns at their bound"),
       output_field("changed", count(), "1", "unknowns that entered or left the active set"),
       output_field("time_s", number(), "s", "since the start of the iteration")});
}

ObjectRulePtr warning_rule() {
  return object_rule(
      "a warning", "warning",
      {output_field("code", choice_value(warning_codes()), "",
                    "what kind of warning, for programs (docs/result-format.md, \"Warnings\")"),
       output_field("message", text(), "", "the sentence, as in warnings"),
       output_field("review", boolean_value(), "",
                    "the answer may be physically empty or wrong although it converged")});
}

ObjectRulePtr material_echo_rule() {
  return object_rule(
      "the material", "material_echo",
      {output_field("mu", number(), "S", "shear modulus μ (from mu, or from E and nu)"),
       output_field("lambda", one_of_value({number_value(), choice_value({"inf"})}, "λ"), "S",
                    "Lamé parameter λ, \"inf\" when incompressible")});
}
ObjectRulePtr statistics_rule() {
  return object_rule(
      "the solver statistics", "solver_statistics",
      {output_field("nested_iterations", list_value(count(), "list of iteration counts"), "1",
                    "iterations of the nested iteration on each coarser level, coarsest first "
                    "(mmg and tnnmg)"),
       output_field("nested_s", number(), "s", "time of the nested iteration (in setup_s)"),
       output_field("accelerated_steps", count(), "1",
                    "iterations whose step the subspace acceleration improved (mmg and tnnmg "
                    "with \"acceleration\": \"subspace\")"),
       output_field("galerkin_rebuilds", count(), "1",
                    "coarse matrices rebuilt for new active sets (truncation)"),
       output_field("safeguard_reductions", count(), "1",
                    "coarse corrections shortened to stay feasible (curved contact boundaries)"),
       output_field("double_precision_smoothers", count(), "1",
                    "vertex-patch smoothers built with factors in double precision because "
                    "single precision was not provably monotone (docs/method.md §4.1; 0 on "
                    "every benchmark)"),
       output_field("galerkin_s", number(), "s", "time of the Galerkin rebuilds"),
       output_field("smoothing_s", number(), "s", "time of the vertex-patch or pointwise sweeps"),
       output_field("strip_s", number(), "s", "time of the contact-strip solves"),
       output_field("coarse_s", number(), "s", "time of the coarsest-level solves")});
}
ObjectRulePtr weights_echo_rule() {
  std::vector<FieldRule> fields;
  for (const char* c : {"c1", "c2", "c3", "c4", "c2_volumetric"})
    fields.push_back(output_field(c, number(), "1", std::string("weight ") + c + " used"));
  fields.push_back(output_field("c3_rule", choice_value({"auto", "given"}), "",
                                "\"auto\" when c3 was chosen from the mesh, \"given\" when the "
                                "case set it"));
  fields.push_back(output_field(
      "c3_limit", number_or_null(), "1",
      "with c3_rule auto: the largest c3 keeping the functional convex on the level it was "
      "computed on (c3 = min(0.1, c3_limit / 2)); null otherwise, without contact or when "
      "unbounded"));
  fields.push_back(output_field(
      "length_scale", number(), "L",
      "ℓ, the power of ten nearest to the body's size (2D: the square root of its area, 3D: "
      "the cube root of its volume): the c1 term is weighted c1 ℓ², so that the weights "
      "balance the terms whatever the unit of length (docs/method.md §2)"));
  return object_rule("the weights", "weights_echo", std::move(fields));
}

std::vector<FieldRule> constraint_fields(int dim) {
  ValueRule obstacles =
      map_value(name_value(1000, "the group name"),
                choice_value({"plane", dim == 3 ? "sphere" : "circle", "gap"}), 100000,
                "object mapping contact groups to obstacle types", "groups");
  obstacles.range.lo = 0;
  return {output_field("direction", choice_value({"body_normal", "obstacle_normal"}), "",
                       "the constraint direction (obstacle_normal when any contact group uses it)"),
          output_field("obstacles", obstacles, "", "the obstacle type of each contact group")};
}

}  // namespace result_parts

namespace {

using namespace result_parts;

ObjectRulePtr zone_rule() {
  ValueRule where = number_or_null();
  return object_rule(
      "the contact zone", "zone",
      {output_field("edges", count(), "1", "contact edges in contact (pressure > 0)"),
       output_field("length", number(), "L",
                    "their total length: an upper bound of the contact width, since the contact "
                    "front lies inside the outermost of them"),
       output_field("width", number(), "L",
                    "the contact width (for Hertz, 2a): the zone's length along the boundary "
                    "with each contact front where the pressure profile reaches zero, "
                    "interpolated from the two outermost loaded edges as c √(a − x); the number "
                    "the CLI and the web page show (docs/result-format.md, \"the contact "
                    "width\")"),
       output_field("s_start", where, "L",
                    "arc length `s` at the start of the first edge in contact; null without one"),
       output_field("s_end", where, "L", "arc length `s` at the end of the last edge in contact"),
       output_field("peak_pressure", number(), "S",
                    "the largest edge pressure (0 without contact)"),
       output_field("peak_location", one_of_value({point_value(), null_value()}, "[x, y] or null"),
                    "L", "midpoint [x, y] of the edge with the peak pressure"),
       output_field("end_edge_length", number(), "L",
                    "mean length of the edges at the ends of the zone: each contact front lies "
                    "within about one such edge, so `length` is resolved to about ± this at "
                    "each end (0 without contact)")});
}

ObjectRulePtr shape_rule() {
  return object_rule(
      "the contact boundary's shape", "contact_shape",
      {output_field("type", choice_value({"none", "line", "arc", "other"}), "",
                    "the vertices of the contact edges lie on a straight line, on one circular "
                    "arc, or neither (each to 1e-6 of their extent); none without contact edges"),
       optional_field("center", point_value(), nullptr, "arc: its centre [x, y] (unit L)"),
       optional_field("radius", number(), nullptr, "arc: its radius (unit L)")});
}

ObjectRulePtr units_echo_rule() {
  ValueRule name = one_of_value({text(), null_value()}, "a string or null");
  return object_rule(
      "the units", "units_echo",
      {output_field("declared", boolean_value(), "", "the case has a units section"),
       output_field("length", name, "", "units.length of the case (L); null when not declared"),
       output_field("stress", name, "", "units.stress of the case (S); null when not declared"),
       output_field("force_per_thickness", name, "",
                    "the unit of S·L, a force per unit thickness: \"N/mm\" for MPa and mm, "
                    "\"N/m\" for Pa and m; null when not declared")});
}

ObjectRulePtr friction_result_rule() {
  ValueRule maybe = number_or_null();
  ValueRule law = object_value(object_rule(
      "a friction law", "friction_law",
      {output_field("law", choice_value({"coulomb", "tresca"}), "", "the law"),
       output_field("coefficient", maybe, "1", "Coulomb's coefficient (null for Tresca)")}));
  ValueRule groups = map_value(name_value(1000, "the group name"), law, 100000,
                               "object mapping frictional contact groups to their laws", "groups");
  groups.range.lo = 0;
  return object_rule(
      "the friction", "friction",
      {output_field("groups", groups, "", "each frictional contact group's law"),
       output_field("updates", count(), "1",
                    "Coulomb: updates of the slip bounds 𝔣|S_n| during the solve (0 for Tresca)"),
       output_field("update_changes", numbers("per update"), "1",
                    "the largest change of a slip bound at each update, relative to the largest "
                    "bound (the first is 1: the bounds of S_n = 0 replaced)"),
       output_field("contraction", maybe, "1",
                    "the mean factor by which successive changes shrank (null for fewer than "
                    "3 updates)"),
       output_field("last_change", maybe, "1",
                    "the last update's change: within solver.friction_tolerance when the "
                    "solve converged by the bounds' change; mmg may also converge with a larger "
                    "one, when the last update moved the iterate by no more than the Coulomb "
                    "residual (docs/method.md §8.4)"),
       output_field("fallback_after", number_or_null(), "1",
                    "Coulomb with mmg: the iteration after which mmg had stalled and pdas "
                    "finished the solve from its iterate (iterations counts both); null when "
                    "mmg finished (docs/method.md §8.4)")});
}

/// A field the result has only with friction (the frictionless result stays as it was).
FieldRule friction_only(FieldRule f) {
  f.required = false;
  return f;
}

ObjectRulePtr stick_zone_rule() {
  ValueRule where = number_or_null();
  return object_rule(
      "the stick zone", "stick_zone",
      {output_field("edges", count(), "1", "contact edges in state stick"),
       output_field("length", number(), "L", "their total length"),
       output_field("s_start", where, "L",
                    "arc length at the start of the first stick edge (null: none)"),
       output_field("s_end", where, "L",
                    "arc length at the end of the last stick edge (null: none)"),
       friction_only(
           output_field("slipping_below_bound", count(), "1",
                        "with friction only: frictional edges in contact that slip with "
                        "|σ_nt| below the slip bound (a consistency check of the discrete "
                        "solution)")),
       friction_only(
           output_field("sticking_at_bound", count(), "1",
                        "with friction only: frictional edges that stick with |σ_nt| at the "
                        "bound")),
       friction_only(
           output_field("front_start", where, "L",
                        "with friction only: arc length of the first stick–slip front, "
                        "located within the edge before s_start from the slip of the step "
                        "(docs/method.md §8.3; null: no stick edge)")),
       friction_only(output_field("front_end", where, "L",
                                  "with friction only: arc length of the last stick–slip front, "
                                  "located within the edge after s_end (null: no stick edge)")),
       friction_only(
           output_field("width", number(), "L",
                        "with friction only: the stick zone's length with its fronts located "
                        "within their edges, summed over the stick runs (for Cattaneo–Mindlin "
                        "2c); between `length` and `length` plus the two edges holding the "
                        "fronts"))});
}

ObjectRulePtr contact_rule() {
  std::vector<FieldRule> fields = {
      output_field("x", numbers("per contact edge"), "L",
                   "midpoint x of each contact edge, in order along the contact boundary"),
      output_field("y", numbers("per contact edge"), "L", "midpoint y of each contact edge"),
      output_field("s", numbers("per contact edge"), "L",
                   "arc length at the midpoint, from the start of the contact boundary (its "
                   "leftmost end)"),
      output_field("length", numbers("per contact edge"), "L", "length of each contact edge"),
      output_field("pressure", numbers("per contact edge"), "S",
                   "contact pressure p = −σ_nn ≥ 0 on each edge (constant on an edge; σ_nn with "
                   "the body's outward normal n)"),
      output_field("gap", numbers("per contact edge"), "L",
                   "the remaining gap g − u·n after deformation, mean over the edge (0 where "
                   "closed; g is the initial gap along the constraint direction)"),
      output_field("active", list_value(boolean_value(), "per contact edge"), "1",
                   "whether the edge is in contact (pressure > 0)"),
      output_field("force", point_value(), "S·L",
                   "[F_x, F_y] = ∫ σn ds over the contact boundary: the force of the obstacle "
                   "on the body, per unit thickness (plane strain)"),
      output_field("zone", object_value(zone_rule()), "", "where the body touches the obstacle"),
      output_field("shear", numbers("per contact edge"), "S",
                   "tangential traction σ_nt on each edge, t = (−n_y, n_x) with the body's "
                   "outward normal n (t runs counter-clockwise around the body); 0 on a "
                   "frictionless edge"),
      output_field("slip", numbers("per contact edge"), "L",
                   "the tangential slip u·t minus its value in the reference state (the "
                   "previous load step; zero without one), mean over the edge"),
      output_field("state", list_value(choice_value({"open", "stick", "slip"}), "per contact edge"),
                   "",
                   "open: not in contact; stick: in contact and not slipping in this load "
                   "step (the slip of the step zero at both vertices, to 1e-6 of the largest); "
                   "slip: in contact and slipping (every edge in contact on frictionless "
                   "contact)"),
      output_field("stick_zone", object_value(stick_zone_rule()), "",
                   "where the body sticks: the edges in state stick"),
      output_field("shape", object_value(shape_rule()), "",
                   "the shape of the contact boundary (a circular arc against a plane is a "
                   "Hertz problem: the web page offers the comparison by this)"),
      output_field("plane_normal", one_of_value({point_value(), null_value()}, "[x, y] or null"),
                   "1",
                   "the unit normal (from the obstacle into the body) of the plane obstacle "
                   "when every contact group has a plane with this normal; null otherwise")};
  for (FieldRule& f : constraint_fields(2)) fields.push_back(std::move(f));
  return object_rule("the contact output", "contact", std::move(fields));
}

ObjectRulePtr functional_rule() {
  return object_rule(
      "the functional", "functional",
      {output_field("total", number(), "scaled", "J at the solution: the sum of the four parts"),
       output_field("momentum", number(), "scaled", "C1 ‖div σ + f‖²"),
       output_field("constitutive", number(), "scaled",
                    "C2 ‖Aσ − ε(u)‖², its volumetric part weighted by weights.c2_volumetric"),
       output_field("contact", number(), "scaled", "C3 ⟨u·n − g, σ_nn⟩"),
       output_field("asymmetry", number(), "scaled", "C4 ‖as σ‖²"),
       output_field("friction", number(), "scaled",
                    "C3 ∫ (σ_nt Δu_t + s |Δu_t|)/μ on frictional edges (docs/method.md §8; 0 "
                    "without friction)"),
       output_field("estimator", number(), "scaled",
                    "J^½, the a posteriori error estimator of the least-squares method"),
       output_field("units", text(), "",
                    "\"stresses scaled by mu\": σ and f enter J divided by μ")});
}

ObjectRulePtr stopping_rule() {
  return object_rule(
      "the stopping rule", "stopping",
      {output_field("rule", choice_value({"kkt_residual", "discretisation"}), "",
                    "solver.tolerance as a rule: a number is kkt_residual, \"discretisation\" "
                    "also stops at the discretisation error (docs/method.md §5.1)"),
       output_field("fraction", number(), "1", "solver.discretisation_fraction used"),
       output_field("converged_by", converged_by_value(), "",
                    "the test the last iterate met: the KKT residual reached tolerance, or the "
                    "algebraic error estimate fell to fraction · estimator, or the KKT residual "
                    "stalled within 10 times its rounding level u ‖|A||x| + |b|‖ (u = 2⁻⁵³) "
                    "before the tolerance (docs/method.md §5.2); none when the solve did not "
                    "converge"),
       output_field("algebraic_error", number_or_null(), "scaled",
                    "estimated algebraic error (J(x) − J(x_h))^½ of the last iterate from the "
                    "decrease of J and its observed rate; null while the last three iterations "
                    "did not decrease J at a rate below 1"),
       output_field("estimator", number(), "scaled",
                    "J^½ of the last iterate, the estimated discretisation error")});
}

ObjectRulePtr mesh_echo_rule() {
  ValueRule params = map_value(name_value(100, "the parameter"), number_value(), 100,
                               "object mapping parameter names to values", "parameters");
  return object_rule(
      "the mesh", "mesh_echo",
      {output_field("source", choice_value({"builtin", "geometry", "msh", "msh_file", "geo_file"}),
                    "", "the mesh source of the case"),
       output_field("size", number(), "L", "mesh.size of the case"),
       output_field("refinements", count(), "1", "mesh.refinements of the case"),
       output_field("order", count(), "1",
                    "mesh.order of the case: 1, or 2 for the order-2 space (dofs and dofs_total "
                    "count its DOFs; the contact output and the VTU are its lowest-order "
                    "interpolant)"),
       optional_field("builtin", choice_value({"square", "hertz", "box", "half_ball"}), nullptr,
                      "the builtin geometry (builtin meshes only)"),
       optional_field("params", params, nullptr,
                      "every parameter of the builtin geometry, defaults included")});
}

ObjectRulePtr timing_rule() {
  return object_rule(
      "the timing", "timing",
      {output_field("mesh_s", number(), "s", "coarse mesh and refinements"),
       output_field("assembly_s", number(), "s",
                    "assembly of the finest level and the level hierarchy"),
       output_field("setup_s", number(), "s",
                    "solver set-up, including the nested iteration on the coarser levels"),
       output_field("solve_s", number(), "s", "set-up and iterations"),
       output_field("total_s", number(), "s", "the whole run")});
}

ObjectRulePtr memory_rule() {
  return object_rule(
      "the memory", "memory",
      {output_field("mesh_mib", number(), "MiB", "peak resident set after meshing"),
       output_field("assembly_mib", number(), "MiB", "after the finest level's assembly"),
       output_field("hierarchy_mib", number(), "MiB",
                    "after the level hierarchy (transfers, patches; mmg, tnnmg, pgs)"),
       output_field("chain_mib", number(), "MiB",
                    "after the Galerkin matrices of the coarser levels (mmg, tnnmg)"),
       output_field("setup_mib", number(), "MiB",
                    "after the solver set-up: nested iteration, smoothers, factorisation analysis"),
       output_field("peak_mib", number(), "MiB",
                    "the whole run (the process's peak: in a process that solved before, the "
                    "larger of both)")});
}

}  // namespace

namespace {

/// The result's fields that say how the solve went: method, convergence, sizes, residuals.
std::vector<FieldRule> outcome_fields(const std::vector<std::string>& reasons, int dim) {
  std::vector<FieldRule> fields = {
      output_field("name", text(), "", "the case's name"),
      output_field("method",
                   dim == 3 ? choice_value({"mmg", "pdas"}) : choice_value(method_names()), "",
                   "the solver method"),
      output_field("converged", boolean_value(), "",
                   "the stopping rule was met: final_kkt_residual ≤ tolerance · "
                   "initial_kkt_residual or, with solver.tolerance \"discretisation\", the "
                   "estimated algebraic error ≤ fraction · J^½, or the KKT residual reached its "
                   "rounding level first (stopping.converged_by says which)"),
      output_field(
          "stop_reason", choice_value(reasons), "",
          "why the iteration stopped: converged, max_iterations (solver.max_iterations "
          "reached first), time_limit (solver.time_limit_s ran out first; the result "
          "is the last iterate), cancelled, or step_failed (a load step could not be solved: "
          "load_steps.stopped_before)"),
      output_field("cancelled", boolean_value(), "", "the job was cancelled while solving"),
      output_field("iterations", count(), "1",
                   "iterations on the finest level (the nested iteration's are in "
                   "solver_statistics)"),
      output_field("tolerance", number(), "1",
                   "solver.tolerance of the case; with \"discretisation\" the KKT tolerance "
                   "that still applies (the default)"),
      output_field("stopping", object_value(stopping_rule()), "",
                   "the stopping rule, which test ended the solve, and the two error "
                   "estimates at the last iterate"),
      output_field("levels", count(), "1", "levels of the hierarchy: mesh.refinements + 1"),
      output_field("dofs", count(), "1", "unknowns of the finest level that are solved for"),
      output_field("dofs_total", count(), "1", "all DOFs of the finest level, fixed ones included"),
      output_field("vertices", count(), "1", "vertices of the finest mesh"),
      dim == 3 ? output_field("tetrahedra", count(), "1", "tetrahedra of the finest mesh")
               : output_field("triangles", count(), "1", "triangles of the finest mesh"),
      output_field("initial_kkt_residual", number(), "scaled",
                   "KKT residual of the initial iterate"),
      output_field("final_kkt_residual", number(), "scaled", "KKT residual at the end"),
      output_field("relative_kkt_residual", number(), "1",
                   "final_kkt_residual / initial_kkt_residual (0 when the initial one is 0)"),
      output_field("asymptotic_rate", number(), "1",
                   "geometric mean of the last (up to) 5 reductions of the KKT residual"),
      output_field("active_bounds", count(), "1",
                   "bounded unknowns at their bound at the end (U_n at the obstacle or S_n at "
                   "zero); not the number of contact edges in contact, see contact.zone.edges"),
      output_field("active", count(), "1", "deprecated: the same as active_bounds")};
  // A 3D result says its dimension; a result without one is 2D's, as a case without one is.
  if (dim == 3)
    fields.insert(fields.begin() + 1,
                  output_field("dimension", integer_value(Range::closed(3, 3)), "", "3"));
  return fields;
}

/// The result's fields that carry what the solve computed and how it ran.
std::vector<FieldRule> solution_fields(const std::vector<std::string>& reasons, int dim) {
  std::vector<FieldRule> fields = {
      optional_field("message", text(), nullptr,
                     "why the solve did not converge or was cancelled (also in warnings)"),
      output_field("warnings", list_value(text(), "list of sentences"), "",
                   "what the user should know (no contact, an initial overlap, a load the "
                   "contact cannot hold, a coarsely resolved contact zone, implausible units, "
                   "non-convergence, ...), each with what it means: the messages of "
                   "warning_details, in the same order"),
      output_field("warning_details", list_value(object_value(warning_rule()), "one per warning"),
                   "", "the warnings with their codes (docs/result-format.md, \"Warnings\")"),
      output_field("review_required", boolean_value(), "",
                   "a warning says that the answer may be physically empty or wrong although "
                   "it converged (a warning with review true); fosls-contact solve then exits "
                   "with code 4"),
      output_field("history", list_value(object_value(history_rule()), "one per iteration"), "",
                   "the initial iterate and every iteration"),
      output_field("solver_statistics", object_value(statistics_rule()), "",
                   "counts and times of the multilevel method's parts"),
      output_field("contact", object_value(dim == 3 ? contact_faces_rule() : contact_rule()), "",
                   "the contact output (empty arrays or zeros when the case has no contact "
                   "group)"),
      output_field("functional", object_value(functional_rule()), "",
                   "the FOSLS functional at the solution and its parts"),
      output_field("units", object_value(units_echo_rule()), "",
                   "the units the case declared (its numbers are used as they are either "
                   "way)"),
      output_field("material", object_value(material_echo_rule()), "",
                   "the material as used (μ, λ)"),
      output_field("mesh", object_value(mesh_echo_rule()), "", "the mesh as given"),
      output_field("weights", object_value(weights_echo_rule()), "", "the weights as used"),
      output_field("timing", object_value(timing_rule()), "", "wall-clock times"),
      output_field("memory", object_value(memory_rule()), "",
                   "peak resident set of the process at the end of each stage"),
      optional_field("adaptivity", object_value(adaptivity_result_rule(dim)), nullptr,
                     "the adaptive loop, step by step (only when the case has an adaptivity "
                     "section; the other fields describe its last step)"),
      optional_field("accuracy", object_value(accuracy_result_rule(dim)), nullptr,
                     "the refinement towards the requested force accuracy, level by level "
                     "(only when the case has an accuracy section; the other fields describe "
                     "its last level)"),
      optional_field("sweep", object_value(sweep_result_rule(choice_value(reasons), dim)), nullptr,
                     "a case with a sweep: every point's force and convergence; the other "
                     "fields are the last point's, except converged and stop_reason, which say "
                     "whether every point converged (and why the first that did not stopped)")};
  // Friction is 2D's only (dimension_support.cpp).
  if (dim == 2)
    fields.push_back(optional_field("friction", object_value(friction_result_rule()), nullptr,
                                    "the friction laws and the updates of Coulomb's slip bounds "
                                    "(only when a contact group has friction)"));
  return fields;
}

}  // namespace

std::vector<std::string> result_parts::stop_reason_names() {
  std::vector<std::string> reasons;
  for (const auto reason : {StopReason::kConverged, StopReason::kMaxIterations,
                            StopReason::kTimeLimit, StopReason::kCancelled})
    reasons.push_back(stop_reason_name(reason));
  reasons.push_back("step_failed");  // a load step could not be solved (load_steps.stopped_before)
  return reasons;
}

ObjectRulePtr result_rule(int dim) {
  const std::vector<std::string> reasons = result_parts::stop_reason_names();
  std::vector<FieldRule> fields = outcome_fields(reasons, dim);
  for (FieldRule& f : solution_fields(reasons, dim)) fields.push_back(std::move(f));
  fields.push_back(optional_field(
      "load_steps", object_value(load_steps_result_rule(fields, dim)), nullptr,
      "a case with load steps: every step's result in order (the case as given is step 0); the "
      "other fields are the last step's, except converged and stop_reason, which say whether "
      "every step converged"));
  return object_rule(dim == 3 ? "the 3D result" : "the result", dim == 3 ? "result3d" : "result",
                     std::move(fields));
}

const char* stop_reason_name(StopReason reason) {
  switch (reason) {
    case StopReason::kConverged:
      return "converged";
    case StopReason::kMaxIterations:
      return "max_iterations";
    case StopReason::kTimeLimit:
      return "time_limit";
    case StopReason::kCancelled:
      return "cancelled";
  }
  return "?";
}

}  // namespace fosls
