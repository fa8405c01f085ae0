#include "case/run/mesh_factory.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/builtin_meshes.hpp"
#include "mesh/coarse_mesh_estimate.hpp"
#include "mesh/msh_reader.hpp"

namespace fosls {

namespace {

const std::string kBuiltinPointer = "/mesh/builtin";
const std::string kSizePointer = "/mesh/size";

/// Copies the known parameters of a built-in geometry into their fields; every unknown or
/// non-finite parameter is an error at /mesh/builtin/<name> (the case JSON's layout).
void take_params(const MeshSpec& spec, const std::vector<std::pair<std::string, double*>>& known,
                 std::vector<CaseError>& errors) {
  for (const auto& [name, value] : spec.params) {
    double* field = nullptr;
    std::string names;
    for (const auto& [k, f] : known) {
      if (k == name) field = f;
      names += (names.empty() ? "" : ", ") + k;
    }
    if (!field)
      errors.push_back({kBuiltinPointer + "/" + name, "'" + spec.builtin + "' has no parameter '" +
                                                          name + "' (its parameters: " + names +
                                                          ")"});
    else if (!std::isfinite(value))
      errors.push_back({kBuiltinPointer + "/" + name, "must be a finite number"});
    else
      *field = value;
  }
}

/// The parameters of the built-in hertz; CaseException for unknown or non-finite ones.
HertzParams hertz_params(const MeshSpec& spec) {
  std::vector<CaseError> errors;
  if (!(spec.size > 0) || !std::isfinite(spec.size))
    errors.push_back({kSizePointer, "the mesh size must be a positive number"});
  HertzParams p;
  take_params(
      spec,
      {{"radius", &p.radius}, {"contact_fraction", &p.contact_fraction}, {"grading", &p.grading}},
      errors);
  p.size = spec.size;
  if (!errors.empty()) throw CaseException(std::move(errors));
  return p;
}

Mesh build_builtin(const MeshSpec& spec, const MeshingControl& control) {
  std::vector<CaseError> errors;
  if (!(spec.size > 0) || !std::isfinite(spec.size))
    errors.push_back({kSizePointer, "the mesh size must be a positive number"});
  if (spec.builtin == "square") {
    SquareParams p;
    take_params(spec, {{"x0", &p.x0}, {"y0", &p.y0}, {"width", &p.width}, {"height", &p.height}},
                errors);
    p.size = spec.size;
    if (!(p.width > 0)) errors.push_back({kBuiltinPointer + "/width", "must be positive"});
    if (!(p.height > 0)) errors.push_back({kBuiltinPointer + "/height", "must be positive"});
    if (!errors.empty()) throw CaseException(std::move(errors));
    const double triangles = 2 * std::ceil(p.width / p.size) * std::ceil(p.height / p.size);
    if (triangles > kMaxCoarseTriangles)
      throw CaseException(kSizePointer,
                          "the mesh size is too small for this square: " +
                              std::to_string(static_cast<long long>(triangles)) +
                              " coarse triangles (at most " +
                              std::to_string(static_cast<long long>(kMaxCoarseTriangles)) +
                              "); use a larger size and refinements instead");
    return make_square(p);
  }
  if (spec.builtin == "hertz") return make_hertz(hertz_params(spec), control);
  throw CaseException(kBuiltinPointer,
                      "unknown built-in geometry '" + spec.builtin + "'; use 'square' or 'hertz'");
}

std::string source_pointer(MeshSpec::Kind kind) {
  switch (kind) {
    case MeshSpec::Kind::kBuiltin:
      return kBuiltinPointer;
    case MeshSpec::Kind::kGeometry:
      return "/mesh/geometry";
    case MeshSpec::Kind::kMsh:
      return "/mesh/msh";
    case MeshSpec::Kind::kGeoFile:
      return "/mesh/geo_file";
  }
  return "/mesh";
}

}  // namespace

Mesh build_coarse_mesh(const MeshSpec& spec, const MeshingControl& control) {
  try {
    switch (spec.kind) {
      case MeshSpec::Kind::kBuiltin:
        return build_builtin(spec, control);
      case MeshSpec::Kind::kGeometry:
        return mesh_from_geometry(spec.geometry, spec.size, control);
      case MeshSpec::Kind::kMsh:
        return mesh_from_msh(spec.msh_text);
      case MeshSpec::Kind::kGeoFile:
        return mesh_from_geo_file(spec.geo_path, spec.size, control);
    }
  } catch (const MeshError& e) {
    throw to_case_exception(e, spec);
  } catch (const std::invalid_argument& e) {
    // Raised by the Mesh constructor and the built-in generators: the source gave a mesh that
    // is not a valid triangulation, or parameters they reject.
    throw CaseException(source_pointer(spec.kind), e.what());
  }
  throw CaseException("/mesh", "unknown kind of mesh source");
}

std::string mesh_source_pointer(const MeshSpec& spec) {
  return spec.msh_path.empty() ? source_pointer(spec.kind) : "/mesh/msh_file";
}

std::optional<GmshOutline> gmsh_outline(const MeshSpec& spec) {
  if (spec.kind == MeshSpec::Kind::kGeometry) {
    SizeField size;
    size.size = spec.size;
    return GmshOutline{spec.geometry, size};
  }
  if (spec.kind != MeshSpec::Kind::kBuiltin || spec.builtin != "hertz") return std::nullopt;
  try {
    return hertz_outline(hertz_params(spec));
  } catch (const std::invalid_argument& e) {
    throw CaseException(kBuiltinPointer, e.what());
  }
}

std::string mesh_problem_pointer(const MeshProblem& problem, const MeshSpec& spec) {
  std::string field = problem.field;
  if (spec.kind == MeshSpec::Kind::kBuiltin && field.rfind("/geometry", 0) == 0)
    return kBuiltinPointer;
  // The geometry's groups are a JSON object: /geometry/groups/<i>[/name | /curves[/<j>]] is
  // the group named by the case, /mesh/geometry/groups/<name>[/<j>].
  const std::string groups = "/geometry/groups/";
  if (spec.kind == MeshSpec::Kind::kGeometry && field.rfind(groups, 0) == 0) {
    std::size_t end = field.find('/', groups.size());
    const std::string index = field.substr(groups.size(), end - groups.size());
    const std::size_t i = std::stoul(index);
    if (i < spec.geometry.groups.size()) {
      std::string rest = end == std::string::npos ? "" : field.substr(end);
      if (rest == "/name" || rest == "/curves") rest.clear();
      if (rest.rfind("/curves/", 0) == 0) rest = rest.substr(7);
      return child_pointer("/mesh/geometry/groups", spec.geometry.groups[i].name) + rest;
    }
  }
  return "/mesh" + field;
}

CaseException to_case_exception(const MeshError& error, const MeshSpec& spec) {
  std::vector<CaseError> errors;
  for (const MeshProblem& p : error.problems())
    errors.push_back({mesh_problem_pointer(p, spec), p.detail});
  return CaseException(std::move(errors));
}

}  // namespace fosls
