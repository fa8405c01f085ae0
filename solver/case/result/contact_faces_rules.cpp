// The `contact` object of a body whose contact boundary is a set of faces (3D; contact_faces.hpp)
// described field by field; the rest of the result's rules are both dimensions' (result_rules.cpp).

#include "case/result/result_rule_parts.hpp"

namespace fosls {

namespace {

using namespace result_parts;

ObjectRulePtr zone3d_rule() {
  const ValueRule where = one_of_value({tuple_value(number_value(), 3, "[x, y, z]"), null_value()},
                                       "[x, y, z] or null");
  return object_rule(
      "the 3D contact zone", "zone3d",
      {output_field("faces", count(), "1", "contact faces in contact (pressure > 0)"),
       output_field("area", number(), "L²",
                    "the area of the zone with its front located within the faces: where the "
                    "p² interpolated from a least-squares plane through the loaded faces' p² "
                    "around each vertex is positive, within the faces with pressure > 0 (≤ "
                    "contact.area, which counts those faces whole)"),
       output_field("symmetry_planes", count(), "1",
                    "the symmetry planes the zone lies against (dirichlet groups holding only "
                    "their normal component at 0, in one plane): the whole zone is 2^k times "
                    "the modelled one"),
       output_field("radius", number(), "L",
                    "√(2^k area/π), k = symmetry_planes: the radius of the disc of the whole "
                    "zone's area, mirrored across its symmetry planes (for Hertz, a)"),
       output_field("box_min", where, "L",
                    "the smallest x, y and z of the faces in contact; null without contact"),
       output_field("box_max", where, "L", "the largest x, y and z of the faces in contact"),
       output_field("peak_pressure", number(), "S",
                    "the largest face pressure (= max_pressure; 0 without contact)"),
       output_field("peak_location", where, "L",
                    "centroid [x, y, z] of the face with the peak pressure; null without one")});
}

ObjectRulePtr line3d_rule() {
  const ValueRule steps = numbers("one per face the line crosses, in order of from");
  return object_rule(
      "the pressure along a line through the 3D contact zone", "line3d",
      {output_field("point", tuple_value(number_value(), 3, "[x, y, z]"), "L",
                    "where s = 0: the zone's centre of pressure (of the whole zone across its "
                    "symmetry planes)"),
       output_field("direction", tuple_value(number_value(), 3, "[x, y, z]"), "1",
                    "the line's unit direction: x's part normal to the contact force (y's where "
                    "x is within 8° of it)"),
       output_field("from", steps, "L",
                    "where the line enters each contact face it crosses, s along direction from "
                    "point (the section of the contact faces by the plane of the line and the "
                    "force)"),
       output_field("to", steps, "L", "where it leaves that face"),
       output_field("pressure", steps, "S",
                    "the face's pressure −σ_nn (constant on a face: the profile is a step "
                    "function, exact)")});
}

}  // namespace

ObjectRulePtr result_parts::contact_faces_rule() {
  std::vector<FieldRule> fields = {
      output_field("force", tuple_value(number_value(), 3, "[F_x, F_y, F_z]"), "S·L²",
                   "∫σn dA over the contact groups: the plane's force on the body"),
      output_field("max_pressure", number(), "S",
                   "the largest face pressure −σ_nn (RT0: one value per face)"),
      output_field("area", number(), "L²", "the area of the contact faces with pressure > 0"),
      output_field("faces", count(), "1", "faces of the contact groups"),
      output_field("faces_in_contact", count(), "1", "of those, the faces with pressure > 0"),
      output_field("zone", object_value(zone3d_rule()), "",
                   "where the body touches the obstacle: its extent and peak, as 2D's zone"),
      output_field("line",
                   one_of_value({object_value(line3d_rule()), null_value()}, "object or null"), "",
                   "the pressure along a line through the zone; null without contact")};
  for (FieldRule& f : constraint_fields(3)) fields.push_back(std::move(f));
  return object_rule("the 3D contact output", "contact3d", std::move(fields));
}

}  // namespace fosls
