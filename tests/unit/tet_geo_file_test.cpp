// 3D meshes from gmsh .geo scripts (3D stage 1), meshed in fosls-mesher as 2D's are: a box with
// its sides in physical surfaces comes back as tetrahedra with those groups and refines; scripts
// without a volume or without physical surfaces, and a missing file, are errors at the field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "mesh/gmsh_mesh.hpp"
#include "mesh/tet_refinement.hpp"

namespace fosls {
namespace {

/// A .geo file with `text`, removed when the test ends.
class GeoFile {
 public:
  explicit GeoFile(const std::string& text)
      : path_(std::filesystem::temp_directory_path() /
              ("fosls_tet_geo_" + std::to_string(::getpid()) + ".geo")) {
    std::ofstream(path_) << text;
  }
  ~GeoFile() { std::filesystem::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

const char* kBox = R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Surface("left") = {1};
Physical Surface("right") = {2};
Physical Surface("front") = {3};
Physical Surface("back") = {4};
Physical Surface("bottom") = {5};
Physical Surface("top") = {6};
)";

std::string field_of(const std::string& geo, double size) {
  const GeoFile file(geo);
  try {
    tet_mesh_from_geo_file(file.path(), size);
  } catch (const MeshError& e) {
    return e.problems().at(0).field + ": " + e.problems().at(0).detail;
  }
  return "no error";
}

TEST(TetGeoFile, ABoxComesBackWithItsGroupsAndRefines) {
  const GeoFile file(kBox);
  const TetMesh coarse = tet_mesh_from_geo_file(file.path(), 0.4);
  EXPECT_EQ(coarse.group_names(),
            (std::vector<std::string>{"left", "right", "front", "back", "bottom", "top"}));
  double volume = 0.0;
  for (int t = 0; t < coarse.num_tets(); ++t) volume += coarse.tet_volume(t);
  EXPECT_NEAR(volume, 1.0, 1e-12);
  for (int f = 0; f < coarse.num_faces(); ++f)
    if (coarse.is_boundary_face(f)) {
      const int g = coarse.face_group(f);
      ASSERT_GE(g, 0);
      EXPECT_NEAR(coarse.face_centroid(f)[g / 2], g % 2, 1e-12);  // make_box's group order
    }
  // The same mesh as MSH text is solved with contact in tet_msh_reader_test; here its
  // refinement keeps the volume and the groups.
  const TetHierarchy h = build_tet_hierarchy(coarse, 1);
  double fine_volume = 0.0;
  for (int t = 0; t < h.finest().num_tets(); ++t) fine_volume += h.finest().tet_volume(t);
  EXPECT_NEAR(fine_volume, 1.0, 1e-12);
  EXPECT_EQ(h.finest().group_names(), coarse.group_names());
}

TEST(TetGeoFile, ScriptsItCannotUseAreErrorsAtTheirField) {
  EXPECT_NE(field_of("Point(1) = {0, 0, 0};\n", 0.4)
                .find("/geo_file: the .geo file defines no "
                      "volume"),
            std::string::npos);
  EXPECT_NE(field_of("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n", 0.4)
                .find("/geo_file: the .geo file defines no physical surfaces"),
            std::string::npos);
  // Only some sides grouped: gmsh's mesh reaches the 3D reader, which names the face.
  EXPECT_NE(field_of("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                     "Physical Surface(\"bottom\") = {5};\n",
                     0.4)
                .find("/geo_file: the mesh gmsh made from it is not usable: the boundary face"),
            std::string::npos);
  EXPECT_NE(field_of(kBox, 1e-4).find("/size: the mesh size is too small"), std::string::npos);
  EXPECT_NE(field_of(kBox, -1.0).find("/size"), std::string::npos);
  try {
    tet_mesh_from_geo_file("/nonexistent/box.geo", 0.4);
    ADD_FAILURE() << "no error";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.problems().at(0).field, "/geo_file");
  }
}

}  // namespace
}  // namespace fosls
