#pragma once
// The symmetry planes a 3D contact zone lies against. A quarter model (hertz_3d_quarter) holds
// a quarter of the zone; its extent as a user reads it (Hertz's a) is the whole zone's, which
// the mirror images across those planes complete.

#include <vector>

#include "case/format/case_spec.hpp"
#include "mesh/tet_mesh.hpp"
#include "post/contact_front.hpp"

namespace fosls {

/// The case's symmetry planes: each a dirichlet group that prescribes one displacement
/// component, the constant 0, and nothing else (a roller), whose faces lie in one plane normal
/// to that component's axis.
std::vector<MirrorPlane> symmetry_planes(const CaseSpec& spec, const TetMesh& mesh);

/// Those of `planes` that hold a vertex of `zone_faces`.
std::vector<MirrorPlane> planes_against(const std::vector<MirrorPlane>& planes, const TetMesh& mesh,
                                        const std::vector<int>& zone_faces);

}  // namespace fosls
