#pragma once
// The contact pressure along a line through a 3D contact zone: the section of the contact
// faces by the plane that holds the line and the contact's normal. RT0's pressure is constant
// on a face, so the profile is a step function: one step per face the plane cuts, exact.

#include <vector>

#include "mesh/tet_mesh.hpp"

namespace fosls {

/// One face's part of the line: s from `from` to `to` along the line, at the face's pressure.
struct SectionStep {
  double from = 0.0;
  double to = 0.0;
  double pressure = 0.0;
};

/// The steps of the faces `faces` that the plane through `origin` spanned by `direction` and
/// `normal` (unit, orthogonal) cuts along a segment of positive length, s measured along
/// `direction` from `origin`, in order of `from`. A face the plane meets in one vertex only is
/// not cut; one whose edge lies in the plane is cut along that edge, and the two faces of such
/// an edge make one step at their mean pressure.
std::vector<SectionStep> pressure_section(const TetMesh& mesh, const std::vector<int>& faces,
                                          const std::vector<double>& pressure, const Point3& origin,
                                          const Point3& direction, const Point3& normal);

}  // namespace fosls
