#include "case/result/result_annotations.hpp"

#include "case/format/units.hpp"
#include "case/result/result_warnings.hpp"
#include "post/contact_shape.hpp"
#include "post/contact_width.hpp"

namespace fosls {

namespace {

using nlohmann::json;

json shape_json(const ContactShape& shape) {
  switch (shape.kind) {
    case ContactShape::Kind::kNone:
      return {{"type", "none"}};
    case ContactShape::Kind::kLine:
      return {{"type", "line"}};
    case ContactShape::Kind::kArc:
      return {{"type", "arc"},
              {"center", {shape.center.x(), shape.center.y()}},
              {"radius", shape.radius}};
    case ContactShape::Kind::kOther:
      break;
  }
  return {{"type", "other"}};
}

/// The unit normal of the plane obstacle when every contact group has a plane with the same
/// normal (what Hertz against a rigid plane needs), else null.
json plane_normal(const CaseSpec& spec) {
  std::optional<Point> normal;
  for (const auto& [name, bc] : spec.boundary) {
    if (bc.type != BoundaryCondition::Type::kContact) continue;
    if (bc.obstacle.kind != Obstacle::Kind::kPlane) return nullptr;
    if (normal && (*normal - bc.obstacle.normal.head<2>()).norm() > 1e-12) return nullptr;
    normal = bc.obstacle.normal.head<2>();
  }
  return normal ? json({normal->x(), normal->y()}) : json(nullptr);
}

/// The warnings of either dimension from the case and the body's size: implausible units, a
/// tangential load on a frictionless contact.
std::vector<ResultWarning> case_warnings(const CaseSpec& spec, double body_size) {
  std::vector<ResultWarning> warnings;
  const std::string units = implausible_units(
      spec.units, youngs_modulus(spec.material.mu, spec.material.lambda), body_size);
  if (!units.empty()) warnings.push_back({"units_implausible", units, true});
  if (auto w = tangential_load_warning(spec)) warnings.push_back(std::move(*w));
  return warnings;
}

/// The accuracy request that was not met, or nothing. A zero force has its own warning
/// (no_contact).
std::optional<ResultWarning> accuracy_warning(const json& result) {
  if (!result.contains("accuracy") || result["accuracy"]["reached"].get<bool>() ||
      result["accuracy"]["stop_reason"] == "no_force")
    return std::nullopt;
  return ResultWarning{"accuracy_not_reached",
                       "the requested force accuracy was not reached: " +
                           result["accuracy"]["stop_message"].get<std::string>(),
                       false};
}

}  // namespace

void annotate_result(json& result, const CaseSpec& spec, const Mesh& finest,
                     const ContactResult& contact, const StrainPeak& strain) {
  result["units"] = units_json(spec.units);
  json& c = result["contact"];
  c["shape"] = shape_json(contact_shape(finest, contact));
  c["plane_normal"] = plane_normal(spec);
  c["zone"]["width"] = contact_width(finest, contact);
  c["zone"]["end_edge_length"] = zone_end_edge_length(contact);

  std::vector<ResultWarning> warnings = case_warnings(spec, finest.diameter());
  for (auto& w : contact_warnings(spec, finest, contact)) warnings.push_back(std::move(w));
  if (auto w = large_strain_warning(strain.strain, strain.largest, strain.where))
    warnings.push_back(std::move(*w));
  if (auto w = accuracy_warning(result)) warnings.push_back(std::move(*w));
  add_warnings(result, warnings);
}

void annotate_result(json& result, const CaseSpec& spec, const FoslsSpace<3>& finest,
                     const FaceContact& contact) {
  result["units"] = units_json(spec.units);
  std::vector<ResultWarning> warnings = case_warnings(spec, finest.mesh().diameter());
  for (auto& w : face_contact_warnings(spec, finest, contact)) warnings.push_back(std::move(w));
  if (auto w = accuracy_warning(result)) warnings.push_back(std::move(*w));
  add_warnings(result, warnings);
}

}  // namespace fosls
