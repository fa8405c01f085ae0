// The `weights` and `solver` sections: the weights of the functional and the iteration.

#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"
#include "case/format/solver_methods.hpp"

namespace fosls {

namespace {

using nlohmann::json;

/// A method that needs smoothing must get at least one step per level.
void check_smoothing(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!checker.usable(j, pointer, {"method", "pre_smoothing", "post_smoothing"})) return;
  const SolverOptions defaults;
  const MethodInfo& method =
      j.contains("method") ? *find_method(j["method"]) : method_info(defaults.method);
  const int steps = j.value("pre_smoothing", defaults.multilevel.pre_smoothing) +
                    j.value("post_smoothing", defaults.multilevel.post_smoothing);
  if (method.needs_smoothing && steps == 0)
    checker.error(child_pointer(pointer, "pre_smoothing"),
                  "pre_smoothing and post_smoothing are both 0; the " + std::string(method.name) +
                      " method needs at least one smoothing step per level");
}

}  // namespace

ObjectRulePtr weights_rule() {
  const Weights w;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the weights";
  r->anchor = "weights";
  r->fields = {
      optional_field("c1", number_value(Range::positive()), w.c1, "weight of ‖div σ + f‖²"),
      optional_field("c2", number_value(Range::positive()), w.c2, "weight of ‖Aσ − ε(u)‖²"),
      optional_field("c3",
                     one_of_value({number_value(Range::non_negative()), choice_value({"auto"})},
                                  "a number >= 0 or the string \"auto\""),
                     "auto",
                     "weight of the contact term ⟨u·n − g, σ_nn⟩; \"auto\": half the largest "
                     "value that keeps the functional convex on this mesh, at most 0.1 "
                     "(docs/method.md §2.1)"),
      optional_field("c4", number_value(Range::non_negative()), w.c4, "weight of ‖as σ‖²"),
      optional_field(
          "c2_volumetric", number_value(Range::closed(0.1, 10)), w.c2_volumetric,
          "weight of the volumetric part ½‖tr(Aσ − ε(u))‖² of the c2 term against "
          "its deviatoric part (1: the plain L² norm, the default). It moves the "
          "contact force on a given mesh: 2 for an incompressible body and 0.5 for "
          "ν = 0.25–0.3 made the force 1.6–10 times more accurate at every refinement on "
          "the measured bodies (docs/method.md §2.2)"),
  };
  return r;
}

Weights read_weights_section(const json& j) {
  Weights w;
  w.c1 = j.value("c1", w.c1);
  w.c2 = j.value("c2", w.c2);
  if (j.contains("c3") && j["c3"].is_number()) {
    w.c3 = j["c3"].get<double>();
    w.c3_auto = false;
  }
  w.c4 = j.value("c4", w.c4);
  w.c2_volumetric = j.value("c2_volumetric", w.c2_volumetric);
  return w;
}

ObjectRulePtr solver_rule() {
  const SolverOptions s;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the solver settings";
  r->anchor = "solver";
  const ValueRule smoothing = integer_value(Range::closed(0, 10));
  r->fields = {
      optional_field("method", choice_value(method_names()), method_info(s.method).name,
                     "the solver method"),
      optional_field(
          "tolerance",
          one_of_value({number_value(Range::open(0, 1)), choice_value({"discretisation"})},
                       "a number in (0, 1) or the string \"discretisation\""),
          s.tolerance,
          "stopping tolerance: the KKT residual relative to the initial iterate's; "
          "\"discretisation\": stop once the estimated algebraic error is "
          "discretisation_fraction times the estimated discretisation error J^½, or "
          "at the default KKT tolerance, whichever comes first (docs/method.md §5.1); "
          "a case with adaptivity stops at \"discretisation\" unless it gives a tolerance. "
          "A tolerance below what double precision can show stops at the residual's rounding "
          "level instead, converged, with a warning (docs/method.md §5.2)"),
      optional_field("discretisation_fraction", number_value(Range::open(0, 1)),
                     s.discretisation_fraction,
                     "with tolerance \"discretisation\": the algebraic error allowed, as a "
                     "fraction of the discretisation error"),
      optional_field("max_iterations", integer_value(Range::closed(1, 100000)), s.max_iterations,
                     "iterations before giving up (the result says \"converged\": false)"),
      optional_field("time_limit_s", number_value(Range::closed(0, 1e7)), s.time_limit_s,
                     "wall-clock seconds the run may take, meshing and assembly included (0: no "
                     "limit); the solve then stops at the last iterate with stop_reason "
                     "time_limit, or, before it has one, the run fails saying so. The "
                     "service's --max-job-seconds still caps a job"),
      optional_field("friction_tolerance", number_value(Range::open(0, 1)), s.friction_tolerance,
                     "Coulomb friction: with mmg, the solve converges when its Coulomb residual "
                     "meets solver.tolerance and either the last update of the slip bounds "
                     "𝔣|σ_nn| changed none by more than this, relative to the largest, or it "
                     "moved the iterate by no more than that residual; pdas uses the first "
                     "test only (docs/method.md §8.4)"),
      optional_field("smoother", choice_value(smoother_names()),
                     smoother_info(s.multilevel.smoother).name, "the smoother"),
      optional_field("pre_smoothing", smoothing, s.multilevel.pre_smoothing,
                     "smoothing steps before the coarse correction"),
      optional_field("post_smoothing", smoothing, s.multilevel.post_smoothing,
                     "smoothing steps after the coarse correction"),
      optional_field("coarse_obstacle", choice_value(coarse_obstacle_names()),
                     coarse_obstacle_info(s.multilevel.projection).name,
                     "how the obstacle of the normal displacement is carried to a coarse "
                     "contact edge"),
      optional_field("cycle", choice_value(cycle_names()), cycle_info(s.multilevel.cycle).name,
                     "mmg and tnnmg: how often a level visits the next coarser one — \"W\" "
                     "twice, \"V\" once, \"F\" an F-cycle then a V-cycle "
                     "(docs/performance.md compares them)"),
      optional_field("acceleration", choice_value({"subspace", "none"}),
                     s.accelerate ? "subspace" : "none",
                     "mmg and tnnmg: \"subspace\" minimises J over the last two steps after "
                     "each iteration, still feasible and monotone (docs/method.md §4.5); "
                     "\"none\" runs the plain method"),
  };
  r->hook = check_smoothing;
  r->notes = "mmg needs pre_smoothing + post_smoothing ≥ 1";
  return r;
}

SolverOptions read_solver_section(const json& j) {
  SolverOptions s;
  if (j.contains("method")) s.method = find_method(j["method"])->method;
  if (j.contains("tolerance") && j["tolerance"].is_string())
    s.stopping = StoppingRule::kDiscretisation;
  else
    s.tolerance = j.value("tolerance", s.tolerance);
  s.discretisation_fraction = j.value("discretisation_fraction", s.discretisation_fraction);
  s.max_iterations = j.value("max_iterations", s.max_iterations);
  s.time_limit_s = j.value("time_limit_s", s.time_limit_s);
  s.friction_tolerance = j.value("friction_tolerance", s.friction_tolerance);
  if (j.contains("smoother")) s.multilevel.smoother = find_smoother(j["smoother"])->type;
  s.multilevel.pre_smoothing = j.value("pre_smoothing", s.multilevel.pre_smoothing);
  s.multilevel.post_smoothing = j.value("post_smoothing", s.multilevel.post_smoothing);
  if (j.contains("coarse_obstacle"))
    s.multilevel.projection = find_coarse_obstacle(j["coarse_obstacle"])->projection;
  if (j.contains("cycle")) s.multilevel.cycle = find_cycle(j["cycle"])->shape;
  if (j.contains("acceleration")) s.accelerate = j["acceleration"] == "subspace";
  return s;
}

}  // namespace fosls
