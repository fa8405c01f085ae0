#pragma once
// The sections of the case JSON, one file each (mesh_section.cpp, geometry_section.cpp,
// material_section.cpp, boundary_section.cpp, solver_section.cpp,
// adaptivity_section.cpp): the rules of the section
// (case_rules.hpp) and its conversion into the CaseSpec. A converter is called only on JSON
// that passed its section's rules, so it needs no checks of its own; absent fields take the
// defaults of the rules.

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "case/admission/case_limits.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_rules.hpp"
#include "case/format/case_spec.hpp"
#include "mesh/coarse_mesh_estimate.hpp"

namespace fosls {

/// The rules of a case's sections in `dim` dimensions: 2 or 3, what the reader checks; 0, what
/// the docs and the schema show of both (docs/architecture.md, "One case path for 2D and 3D").
ObjectRulePtr mesh_rule(const CaseReadOptions& options, int dim);
/// mesh.builtin: square and hertz (2D), box and half_ball (3D); the other dimension's refused.
ObjectRulePtr builtin_rule(int dim);
ValueRule builtin_value(int dim);
std::string builtin_meaning(int dim);
/// Reads mesh.builtin (a name or an object) into `m`: its kind, name and every parameter.
void read_builtin(const nlohmann::json& j, MeshSpec& m);
/// Estimated coarse triangles of a 2D builtin with edge length `size`.
double builtin_triangles(const nlohmann::json& j, double size);
/// The rules of mesh.geo_file and mesh.msh_file (command line only, the file must exist; an msh
/// file must hold msh text within the limit, `contents` says what for the docs), shared by the
/// mesh section of both dimensions.
ValueRule geo_file_value(const CaseLimits& limits);
ValueRule msh_file_value(const CaseLimits& limits, const std::string& contents);
/// The rule of mesh.msh, gmsh ASCII 4.1 text given in the case (2D and 3D).
ValueRule msh_text_value(const CaseLimits& limits);
/// The text of an msh_file its rule accepted, read once more within the rule's limit (empty when
/// it cannot be read now: the mesh reader then names the problem).
std::string read_msh_file(const std::string& path);
MeshSpec read_mesh_section(const nlohmann::json& j);

ObjectRulePtr geometry_rule(const CaseReadOptions& options);
GeometrySpec read_geometry_section(const nlohmann::json& j);
/// The mesh layer's estimate of the coarse mesh of `geometry` with edge length `size`.
CoarseMeshEstimate estimated_coarse_mesh(const GeometrySpec& geometry, double size);

ObjectRulePtr material_rule();
Material read_material_section(const nlohmann::json& j);

ValueRule boundary_rule(const CaseReadOptions& options, int dim);
std::map<std::string, BoundaryCondition> read_boundary_section(const nlohmann::json& j);
/// The contact variant of a boundary condition: its obstacle, friction and direction
/// (obstacle_section.cpp).
ObjectVariant contact_variant(const CaseReadOptions& options, int dim);
/// The obstacle of a contact condition that passed contact_variant's rules: `obstacle`, or the
/// plane of the condition's own point and normal.
Obstacle read_obstacle(const nlohmann::json& condition);

ObjectRulePtr weights_rule();
Weights read_weights_section(const nlohmann::json& j);

ObjectRulePtr solver_rule();
SolverOptions read_solver_section(const nlohmann::json& j);

/// The hook of a dirichlet condition whose `displacement` may have null (free) components: an
/// error at the field when every component is null, which prescribes nothing; `why` says so and
/// what to give instead (2D and 3D, boundary_section.cpp).
ObjectHook some_displacement_prescribed(std::string why);

/// The rule of a refinement loop's max_dofs (adaptivity, accuracy): 1 up to the case limit.
ValueRule finest_level_dofs_value(const CaseLimits& limits);
ObjectRulePtr adaptivity_rule(const CaseReadOptions& options);
AdaptivitySpec read_adaptivity_section(const nlohmann::json& j, const CaseLimits& limits);
ObjectRulePtr accuracy_rule(const CaseReadOptions& options);
AccuracySpec read_accuracy_section(const nlohmann::json& j, const CaseLimits& limits);
/// Settles accuracy.refinement's default (adaptive in 3D, uniform in 2D: docs/performance.md,
/// "Accuracy on demand") and refuses "adaptive" with friction or mesh.order 2, which the
/// adaptive loop does not take yet.
void settle_accuracy_refinement(CaseSpec& spec, std::vector<CaseError>& errors);
ObjectRulePtr sweep_rule(const CaseReadOptions& options);
/// Reads the case at each value of its sweep into spec.sweep_points; a value that makes the
/// case invalid is an error at /sweep/values/<i> naming the field and the reason.
void read_sweep_section(const nlohmann::json& case_json, const CaseReadOptions& options,
                        CaseSpec& spec, std::vector<CaseError>& errors);

ValueRule load_steps_rule(const CaseReadOptions& options);
/// Reads the case after each load step into spec.load_step_points (with the step's changes in
/// spec.load_step_changes); a bad pointer or a value that makes the case invalid is an error at
/// /load_steps/<k>/<pointer> or /load_steps/<k> naming the field and the reason.
void read_load_steps_section(const nlohmann::json& case_json, const CaseReadOptions& options,
                             CaseSpec& spec, std::vector<CaseError>& errors);

/// [f_x, f_y] or [f_x, f_y, f_z], ...: `dim` numbers or expressions (vector_value).
ValueRule scalars_value(const CaseReadOptions& options, int dim);
Scalar read_scalar(const nlohmann::json& j);
Point read_point(const nlohmann::json& j);
/// Two or three numbers as a 3-vector (z = 0 for two).
Point3 read_vector(const nlohmann::json& j);
/// Two or three scalars (the third empty for two).
std::array<Scalar, 3> read_scalars(const nlohmann::json& j);

}  // namespace fosls
