// The 3D case format ("dimension": 3): its rules, stated once as data like the 2D case's, and
// their conversion into a Case3dSpec. Material and solver are the 2D case's sections.

#include "case/case3d_reader.hpp"

#include <algorithm>

#include "case/case_sections.hpp"
#include "case/contact3d_section.hpp"
#include "case/early_group_check.hpp"
#include "case/expression.hpp"
#include "case/rule_checker.hpp"

namespace fosls {

namespace {

using nlohmann::json;

ValueRule cells_value(int max) { return integer_value(Range::closed(1, max)); }

ObjectRulePtr builtin3d_rule() {
  const HalfBallSpec ball;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the builtin 3D geometry";
  r->anchor = "builtin3d";
  r->discriminator = "name";
  r->discriminator_meaning = "the builtin 3D geometry, box or half_ball";
  r->variants = {
      {"box",
       "the box",
       "the box [0, lx] × [0, ly] × [0, lz] in cubes of six tetrahedra; boundary groups left, "
       "right (x = 0, lx), front, back (y), bottom, top (z)",
       {optional_field("lengths", vector3_value("[lx, ly, lz]"), json::array({1, 1, 1}),
                       "the edge lengths [lx, ly, lz] (each > 0)"),
        optional_field("cells", tuple_value(cells_value(64), 3, "an array of 3 integers"),
                       json::array({2, 2, 2}), "cubes along x, y and z (each 1 to 64)")},
       [](const json& j, const std::string& pointer, RuleChecker& checker) {
         if (!j.contains("lengths")) return;
         for (const auto& l : j["lengths"])
           if (!(l.get<double>() > 0)) {
             checker.error(child_pointer(pointer, "lengths"), "every length must be > 0");
             return;
           }
       },
       "every length is > 0"},
      {"half_ball",
       "the half ball",
       "the half ball {|x| ≤ R, z ≤ 0} centred at the origin, flat face up, graded towards its "
       "pole (0, 0, −R); boundary groups top (z = 0), contact (the sphere within "
       "contact_fraction · R of the axis) and free (the rest of the sphere)",
       {optional_field("radius", number_value(Range::positive()), ball.radius, "radius R"),
        optional_field("cells", cells_value(16), ball.cells,
                       "Kuhn cubes along the depth of the coarse mesh; 2 × cells across"),
        optional_field("grading", number_value(Range::closed(1, 4)), ball.grading,
                       "element sizes grow as (distance to the pole)^(grading − 1)"),
        optional_field("contact_fraction", number_value(Range::open(0, 1)), ball.contact_fraction,
                       "sphere faces within contact_fraction · R of the axis form the group "
                       "contact"),
        optional_field("quarter", boolean_value(), ball.quarter,
                       "only the quarter x ≥ 0, y ≥ 0, with the extra groups symmetry_x (x = 0) "
                       "and symmetry_y (y = 0) for rollers: a quarter of the unknowns")},
       {},
       ""},
  };
  return r;
}

ObjectRulePtr mesh3d_rule(const CaseReadOptions& options) {
  const Mesh3dSpec defaults;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the 3D mesh";
  r->anchor = "mesh3d";
  ValueRule builtin =
      one_of_value({choice_value({"box", "half_ball"}), object_value(builtin3d_rule())},
                   "the name of a builtin 3D geometry (\"box\" or \"half_ball\") "
                   "or an object {\"name\": ..., parameters}");
  r->fields = {
      optional_field("builtin", builtin, nullptr, "a shipped 3D geometry, box or half_ball"),
      optional_field("msh", msh_text_value(options.limits), nullptr,
                     "the text of a gmsh mesh file (ASCII 4.1) of tetrahedra"),
      optional_field("msh_file", msh_file_value(options.limits, "msh text with tetrahedra"),
                     nullptr, "the path of a gmsh mesh file (ASCII 4.1) of tetrahedra"),
      optional_field("geo_file", geo_file_value(options.limits), nullptr,
                     "the path of a gmsh .geo script, meshed in 3D"),
      optional_field("size", number_value(Range::positive()), defaults.size,
                     "target edge length of the coarse mesh (geo_file only)"),
      optional_field("refinements", integer_value(Range::closed(0, kMax3dRefinements)),
                     defaults.refinements,
                     "uniform refinements (each tetrahedron into 8); the multilevel hierarchy "
                     "has refinements + 1 levels"),
  };
  r->exclusive = {{{{"builtin"}, {"msh"}, {"msh_file"}, {"geo_file"}},
                   "no mesh source: give exactly one of builtin, msh, msh_file or geo_file",
                   "give exactly one mesh source, not {given}"}};
  return r;
}

ObjectRulePtr condition3d_rule(const CaseReadOptions& options) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "a 3D boundary condition";
  r->anchor = "condition3d";
  r->discriminator = "type";
  r->discriminator_meaning = "dirichlet, neumann, pressure or contact";
  const ValueRule component = scalar3_value(options.limits.max_expression_length);
  r->variants = {
      {"dirichlet",
       "a dirichlet condition",
       "prescribed displacement",
       {required_field(
           "displacement",
           tuple_value(one_of_value({component, null_value()},
                                    "a number, an expression of x, y and z, or null"),
                       3, "an array of 3 numbers, expressions or null"),
           "the prescribed displacement [u_x, u_y, u_z]; null leaves that component free with "
           "zero traction (a roller or symmetry plane: [0, null, null] on a plane x = const)")},
       // [0, null, null] is a roller; [null, null, null] would prescribe nothing.
       some_displacement_prescribed(
           "all three components are null, which prescribes nothing; a boundary free in every "
           "direction is a neumann condition with traction [0, 0, 0]"),
       "not all three components null"},
      {"neumann",
       "a neumann condition",
       "prescribed traction σn",
       {required_field("traction",
                       tuple_value(component, 3, "an array of 3 numbers or expressions"),
                       "the prescribed traction [t_x, t_y, t_z]: numbers or expressions of x, y "
                       "and z")},
       {},
       ""},
      {"pressure",
       "a pressure condition",
       "a normal pressure: the traction t = −p n with the body's outward normal n",
       {required_field("pressure", component,
                       "the pressure p: a number or an expression of x, y and z; p > 0 pushes "
                       "into the body")},
       {},
       ""},
      contact3d_variant(options),
  };
  return r;
}

Mesh3dSpec read_mesh3d_section(const json& j) {
  Mesh3dSpec m;
  m.size = j.value("size", m.size);
  m.refinements = j.value("refinements", m.refinements);
  if (const auto it = j.find("builtin"); it != j.end()) {
    const json given = it->is_string() ? json::object() : *it;
    const std::string name =
        it->is_string() ? it->get<std::string>() : (*it)["name"].get<std::string>();
    if (name == "box") {
      m.kind = Mesh3dSpec::Kind::kBox;
      if (given.contains("lengths")) m.lengths = read_vector3(given["lengths"]);
      if (given.contains("cells"))
        for (int i = 0; i < 3; ++i) m.cells[i] = given["cells"][i].get<int>();
    } else {
      m.kind = Mesh3dSpec::Kind::kHalfBall;
      m.ball.radius = given.value("radius", m.ball.radius);
      m.ball.cells = given.value("cells", m.ball.cells);
      m.ball.grading = given.value("grading", m.ball.grading);
      m.ball.contact_fraction = given.value("contact_fraction", m.ball.contact_fraction);
      m.ball.quarter = given.value("quarter", m.ball.quarter);
    }
  } else if (const auto it = j.find("msh"); it != j.end()) {
    m.kind = Mesh3dSpec::Kind::kMsh;
    m.msh_text = it->get<std::string>();
  } else if (const auto it = j.find("msh_file"); it != j.end()) {
    m.kind = Mesh3dSpec::Kind::kMsh;  // checked readable by its rule; the text is the mesh
    m.path = it->get<std::string>();
    m.msh_text = read_msh_file(m.path);
  } else {
    m.kind = Mesh3dSpec::Kind::kGeoFile;
    m.path = j["geo_file"].get<std::string>();
  }
  return m;
}

Condition3d read_condition3d(const json& j) {
  Condition3d c;
  const std::string type = j["type"].get<std::string>();
  if (type == "contact") {
    c.type = Condition3d::Type::kContact;
    c.obstacle = read_obstacle3d(j);
    return c;
  }
  if (type == "pressure") {
    c.type = Condition3d::Type::kPressure;
    c.values[0] = compile_scalar_3d(read_scalar(j["pressure"]));
    return c;
  }
  c.type = type == "dirichlet" ? Condition3d::Type::kDirichlet : Condition3d::Type::kNeumann;
  const json& v = j[type == "dirichlet" ? "displacement" : "traction"];
  c.prescribed = 0;
  for (int i = 0; i < 3; ++i) {
    if (v[i].is_null()) continue;
    c.values[i] = compile_scalar_3d(read_scalar(v[i]));
    c.prescribed |= 1 << i;
  }
  return c;
}

}  // namespace

bool is_3d_case(const json& j) {
  return j.is_object() && j.contains("dimension") && j["dimension"].is_number() &&
         j["dimension"] == 3;
}

ObjectRulePtr case3d_rule(const CaseReadOptions& options) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "the 3D case";
  r->anchor = "case3d";
  r->fields = {
      optional_field("name", name_value(options.limits.max_name_length, "the name"), "case",
                     "a label copied to the result"),
      required_field("dimension", integer_value(Range::closed(3, 3)), "3: a 3D case"),
      required_field("mesh", object_value(mesh3d_rule(options)), "the mesh of the body"),
      required_field("material", object_value(material_rule()),
                     "the material (mu and lambda, or E and nu)"),
      optional_field("body_force", vector3_value("[f_x, f_y, f_z]"), json::array({0, 0, 0}),
                     "volume force f = [f_x, f_y, f_z]"),
      required_field(
          "boundary",
          map_value(name_value(options.limits.max_name_length, "the boundary group name"),
                    object_value(condition3d_rule(options)), options.limits.max_geometry_entities,
                    "object mapping boundary group names to conditions", "conditions"),
          "the conditions on the boundary groups"),
      optional_field("solver", object_value(solver_rule()), nullptr,
                     "the iteration and its parameters (methods mmg and pdas)"),
  };
  return r;
}

Case3dReadResult read_case_3d(const json& j, const CaseReadOptions& options) {
  Case3dReadResult result;
  RuleChecker checker(options);
  checker.check_object(j, *case3d_rule(options), "");
  result.errors = checker.take_errors();
  if (!result.errors.empty()) return result;
  Case3dSpec spec;
  spec.name = j.value("name", spec.name);
  spec.mesh = read_mesh3d_section(j["mesh"]);
  spec.material = read_material_section(j["material"]);
  if (j.contains("body_force"))
    for (int i = 0; i < 3; ++i) spec.body_force[i] = j["body_force"][i].get<double>();
  for (const auto& [name, condition] : j["boundary"].items())
    spec.boundary[name] = read_condition3d(condition);
  if (j.contains("solver")) spec.solver = read_solver_section(j["solver"]);
  if (std::none_of(spec.boundary.begin(), spec.boundary.end(),
                   [](const auto& b) { return b.second.type == Condition3d::Type::kDirichlet; }))
    result.errors.push_back(no_dirichlet_problem());
  if (spec.solver.method != SolverMethod::kMmg && spec.solver.method != SolverMethod::kPdas)
    result.errors.push_back({"/solver/method", "a 3D case is solved by mmg (the default) or pdas"});
  if (result.errors.empty()) result.spec = std::move(spec);
  return result;
}

}  // namespace fosls
