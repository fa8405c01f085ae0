#pragma once
// The contact output of a body whose contact boundary is a set of faces (3D; 2D's boundary of
// edges is post/contact_output's ContactResult): the force as a 3-vector, the area and extent
// of the faces in contact and where the pressure peaks (docs/result-format.md, "3D results"),
// and the warnings 2D gives for the same findings, with the same codes.

#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "assembly/discretization.hpp"
#include "case/format/case_spec.hpp"
#include "case/result/result_warnings.hpp"
#include "case/result/zone_line.hpp"

namespace fosls {

struct FaceContact {
  Point3 force = Point3::Zero();
  double max_pressure = 0.0;
  double area = 0.0;  ///< of the faces with p > 0
  /// Of the part of those faces within the front located by post/contact_front.hpp.
  double front_area = 0.0;
  /// The symmetry planes the zone lies against (symmetry_planes.hpp): the whole zone is
  /// 2^symmetry_planes times the modelled one.
  int symmetry_planes = 0;
  int faces = 0;  ///< of the contact groups
  int faces_in_contact = 0;
  Point3 peak_at = Point3::Zero();  ///< centroid of the face with the largest pressure
  std::optional<ZoneLine> line;     ///< the pressure along a line through the zone
  /// The bounding box of the faces with p > 0 (empty: lo > hi).
  Point3 lo = Point3::Constant(std::numeric_limits<double>::infinity());
  Point3 hi = -Point3::Constant(std::numeric_limits<double>::infinity());
};

/// The contact output of the finest level's full DOF vector; the case names the symmetry planes.
FaceContact face_contact(const CaseSpec& spec, const Discretization<3>& disc, const Vector& x_full);

/// The result's `contact` object but for the constraint's direction and obstacles, which
/// result_json adds in both dimensions.
nlohmann::json face_contact_json(const FaceContact& c);

/// An initial overlap, a zone resolved by few faces, no contact, and contact vertices that a
/// roller displaced.
std::vector<ResultWarning> face_contact_warnings(const CaseSpec& spec, const FoslsSpace<3>& space,
                                                 const FaceContact& c);

}  // namespace fosls
