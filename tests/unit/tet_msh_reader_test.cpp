// The MSH 4.1 reader for tetrahedra (3D stage 1): a cube meshed by gmsh itself, read, refined and
// solved with contact (mmg = pdas); hand-written text for the refusals, each a MeshError at /msh
// that names what is wrong.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <sstream>

#include "../gmsh_text.hpp"
#include "../tet_problems.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/tet_msh_reader.hpp"

namespace fosls {
namespace {

/// MSH 4.1 text of the unit cube meshed by gmsh, its six sides in physical surfaces named and
/// numbered as make_box's groups (left, right, front, back, bottom, top), the volume physical.
std::string cube_msh(double size) {
  return testing::gmsh_msh_text(3, [size] {
    gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1, 1);
    gmsh::model::occ::synchronize();
    const char* names[] = {"left", "right", "front", "back", "bottom", "top"};
    std::vector<std::pair<int, int>> surfaces;
    gmsh::model::getEntities(surfaces, 2);
    for (const auto& [dim, tag] : surfaces) {
      // Which side: the axis and end of the surface's centre.
      double c[3];
      gmsh::model::occ::getCenterOfMass(dim, tag, c[0], c[1], c[2]);
      for (int side = 0; side < 6; ++side)
        if (std::abs(c[side / 2] - side % 2) < 1e-9) {
          gmsh::model::addPhysicalGroup(2, {tag}, side + 1);
          gmsh::model::setPhysicalName(2, side + 1, names[side]);
        }
    }
    gmsh::model::addPhysicalGroup(3, {1}, 7);
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  });
}

TEST(TetMshReader, ReadsGmshsCubeRefinesAndSolvesContact) {
  const TetMesh coarse = tet_mesh_from_msh(cube_msh(0.5));
  EXPECT_EQ(coarse.group_names(),
            (std::vector<std::string>{"left", "right", "front", "back", "bottom", "top"}));
  double volume = 0.0;
  for (int t = 0; t < coarse.num_tets(); ++t) volume += coarse.tet_volume(t);
  EXPECT_NEAR(volume, 1.0, 1e-12);
  for (int f = 0; f < coarse.num_faces(); ++f) {
    if (!coarse.is_boundary_face(f)) continue;
    const int g = coarse.face_group(f);
    ASSERT_GE(g, 0);
    const Point3 c = coarse.face_centroid(f);
    EXPECT_NEAR(c[g / 2], g % 2, 1e-12) << "face in group " << coarse.group_names()[g];
  }
  // The 3D Signorini block on gmsh's mesh: the same problem as on make_box's.
  const Discretization<3> disc(build_tet_hierarchy(coarse, 1), testing::signorini_block(1.0));
  const testing::MmgAndPdas s =
      testing::solve_with_mmg_and_pdas(disc, disc.build_level_hierarchy());
  EXPECT_TRUE(s.mmg.converged);
  EXPECT_TRUE(s.pdas.converged);
  EXPECT_GT(s.force.z(), 0.0);
  EXPECT_NEAR(s.force.z(), s.pdas_force.z(), 1e-6 * s.pdas_force.z());
  std::printf("gmsh cube: %d tetrahedra, refined %d; F_z %.6f in %d mmg iterations\n",
              coarse.num_tets(), disc.meshes().finest().num_tets(), s.force.z(), s.mmg.iterations);
}

/// One tetrahedron (and, with `second`, a second one on its slanted face), its faces in the
/// physical surfaces 1 "bottom" and 2 "rest"; `bottom` and `rest` are their triangle blocks.
std::string tet_text(const std::string& bottom, const std::string& rest, bool second = false,
                     const std::string& tets = "3 1 4 1\n5 1 2 3 4\n") {
  std::string elements = bottom + rest + tets;
  int blocks = 0, count = 0;
  for (std::istringstream in(elements); !in.eof();) {
    std::string line;
    std::getline(in, line);
    if (line.empty()) continue;
    std::istringstream header(line);
    int dim, entity, type, n;
    header >> dim >> entity >> type >> n;
    ++blocks;
    count += n;
    for (int k = 0; k < n; ++k) std::getline(in, line);
  }
  std::ostringstream t;
  t << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    << "$PhysicalNames\n2\n2 1 \"bottom\"\n2 2 \"rest\"\n$EndPhysicalNames\n"
    << "$Entities\n0 0 2 1\n1 0 0 0 1 1 0 1 1 0\n2 0 0 0 1 1 1 1 2 0\n1 0 0 0 1 1 1 0 0\n"
    << "$EndEntities\n"
    << "$Nodes\n1 " << (second ? 5 : 4) << " 1 " << (second ? 5 : 4) << "\n3 1 0 "
    << (second ? 5 : 4) << "\n1\n2\n3\n4\n"
    << (second ? "5\n" : "") << "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    << (second ? "1 1 1\n" : "") << "$EndNodes\n"
    << "$Elements\n"
    << blocks << " " << count << " 1 " << count << "\n"
    << elements << "$EndElements\n";
  return t.str();
}

const std::string kBottom = "2 1 2 1\n1 1 2 3\n";
const std::string kRest = "2 2 2 3\n2 1 2 4\n3 1 3 4\n4 2 3 4\n";

std::string error_of(const std::string& text) {
  try {
    tet_mesh_from_msh(text);
  } catch (const MeshError& e) {
    EXPECT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].field, "/msh");
    return e.problems()[0].detail;
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(TetMshReader, ReadsOneTetrahedronWithItsGroups) {
  const TetMesh m = tet_mesh_from_msh(tet_text(kBottom, kRest));
  EXPECT_EQ(m.num_vertices(), 4);
  EXPECT_EQ(m.num_tets(), 1);
  EXPECT_EQ(m.group_names(), (std::vector<std::string>{"bottom", "rest"}));
  int bottom = 0;
  for (int f = 0; f < m.num_faces(); ++f)
    if (m.face_group(f) == 0) {
      ++bottom;
      EXPECT_NEAR(m.face_normal(f).z(), -1.0, 1e-15);  // outward
    }
  EXPECT_EQ(bottom, 1);
}

TEST(TetMshReader, RefusesWhatItCannotUseNamingTheReason) {
  EXPECT_NE(error_of(tet_text(kBottom, "")).find("is on no physical surface"), std::string::npos);
  EXPECT_NE(error_of(tet_text(kBottom, kRest, false, "3 1 5 1\n5 1 2 3 4 1 2 3 4\n"))
                .find("hexahedra, prisms or pyramids"),
            std::string::npos);
  EXPECT_NE(error_of(tet_text(kBottom, kRest, false, "3 1 11 1\n5 1 2 3 4 1 2 3 4 1 2\n"))
                .find("second-order"),
            std::string::npos);
  EXPECT_NE(error_of(tet_text(kBottom, kRest, false, "")).find("no tetrahedra"), std::string::npos);
  EXPECT_NE(error_of(tet_text("2 1 2 1\n1 1 2 5\n", kRest, true, "3 1 4 2\n5 1 2 3 4\n6 2 3 4 5\n"))
                .find("not a face of any tetrahedron"),
            std::string::npos);
  // The face the two tetrahedra share, put in "bottom": a group inside the body.
  const std::string outside = "2 2 2 6\n2 1 2 3\n3 1 2 4\n4 1 3 4\n7 2 3 5\n8 2 4 5\n9 3 4 5\n";
  EXPECT_NE(
      error_of(tet_text("2 1 2 1\n1 2 3 4\n", outside, true, "3 1 4 2\n5 1 2 3 4\n6 2 3 4 5\n"))
          .find("lies between two tetrahedra"),
      std::string::npos);
  EXPECT_NE(error_of(tet_text(kBottom, kRest, false, "3 1 4 1\n5 1 2 3 9\n")).find("not in $Nodes"),
            std::string::npos);
}

}  // namespace
}  // namespace fosls
