// The pressure along a line through a 3D contact zone (post/pressure_section.hpp): the section of
// the bottom faces of a box by a plane, as steps of the faces' constant pressures.
#include "post/pressure_section.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh/tet_refinement.hpp"

namespace fosls {
namespace {

struct Bottom {
  TetMesh mesh = make_box({4, 4, 1}, Point3(1, 1, 0.25));
  std::vector<int> faces;
  std::vector<double> pressure;
  Bottom() {
    const auto& names = mesh.group_names();
    const int bottom =
        static_cast<int>(std::find(names.begin(), names.end(), "bottom") - names.begin());
    pressure.assign(mesh.num_faces(), 0.0);
    for (int f = 0; f < mesh.num_faces(); ++f)
      if (mesh.face_group(f) == bottom) {
        faces.push_back(f);
        pressure[f] = mesh.face_centroid(f).x();  // a different value on each face
      }
  }
};

/// The steps tile [lo, hi] without gap or overlap, in order.
void expect_tiling(const std::vector<SectionStep>& steps, double lo, double hi) {
  ASSERT_FALSE(steps.empty());
  EXPECT_NEAR(steps.front().from, lo, 1e-12);
  EXPECT_NEAR(steps.back().to, hi, 1e-12);
  for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
    EXPECT_LT(steps[k].from, steps[k].to);
    EXPECT_NEAR(steps[k].to, steps[k + 1].from, 1e-12) << k;
  }
}

TEST(PressureSection, ALineAcrossTheFacesTilesItAndCarriesEachFacesPressure) {
  const Bottom b;
  // Through (0.3, 0.37), a point on no mesh edge, along x: s from −0.3 to 0.7.
  const Point3 origin(0.3, 0.37, 0.0);
  const auto steps =
      pressure_section(b.mesh, b.faces, b.pressure, origin, Point3::UnitX(), Point3::UnitZ());
  expect_tiling(steps, -0.3, 0.7);
  // Each step's pressure is that of the face it crosses: the face's centroid x lies within a
  // quarter (a cell) of the step's.
  for (const SectionStep& s : steps)
    EXPECT_LT(std::abs(s.pressure - (0.3 + 0.5 * (s.from + s.to))), 0.25);
}

TEST(PressureSection, ALineAlongMeshEdgesIsOneStepPerEdgeAtTheMeanOfItsTwoFaces) {
  const Bottom b;
  // y = 0.5 runs along the cells' edges: each edge has a face on either side.
  const auto steps = pressure_section(b.mesh, b.faces, b.pressure, Point3(0.0, 0.5, 0.0),
                                      Point3::UnitX(), Point3::UnitZ());
  expect_tiling(steps, 0.0, 1.0);
  EXPECT_EQ(steps.size(), 4u);  // one per cell edge of length 0.25
  for (const SectionStep& s : steps) EXPECT_NEAR(s.to - s.from, 0.25, 1e-12);
}

TEST(PressureSection, APlaneThatMissesTheFacesHasNoSteps) {
  const Bottom b;
  EXPECT_TRUE(pressure_section(b.mesh, b.faces, b.pressure, Point3(0.0, 2.0, 0.0), Point3::UnitX(),
                               Point3::UnitZ())
                  .empty());
}

}  // namespace
}  // namespace fosls
