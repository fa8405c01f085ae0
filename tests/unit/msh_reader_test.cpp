// The MSH 4.1 reader on text written by gmsh itself, and on corrupt text of many kinds: every
// failure must be a CaseException at /mesh/msh that names what was expected, never a crash.
// The reader itself throws MeshError at /msh (relative to the mesh section); the case layer
// (build_coarse_mesh) turns that into the pointer the user sees, which is what is checked.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "../gmsh_text.hpp"
#include "case/format/case_error.hpp"
#include "case/run/mesh_factory.hpp"
#include "mesh/msh_reader.hpp"

namespace fosls {
namespace {

struct SquareOptions {
  bool physical_surface = true;
  bool all_curves_physical = true;
  int element_order = 1;
};

/// MSH 4.1 text of the unit square meshed by gmsh: physical curves "bottom" (tag 1) and
/// "rest of boundary" (tag 2, a name with spaces) and, optionally, the surface.
std::string square_msh(const SquareOptions& opt = {}) {
  return testing::gmsh_msh_text(2, [&opt] {
    namespace geo = gmsh::model::geo;
    geo::addPoint(0, 0, 0, 0.3, 1);
    geo::addPoint(1, 0, 0, 0.3, 2);
    geo::addPoint(1, 1, 0, 0.3, 3);
    geo::addPoint(0, 1, 0, 0.3, 4);
    for (int i = 1; i <= 4; ++i) geo::addLine(i, i % 4 + 1, i);
    geo::addCurveLoop({1, 2, 3, 4}, 1);
    geo::addPlaneSurface({1}, 1);
    geo::addPhysicalGroup(1, {1}, 1);
    gmsh::model::setPhysicalName(1, 1, "bottom");
    geo::addPhysicalGroup(1, opt.all_curves_physical ? std::vector<int>{2, 3, 4} : std::vector{2},
                          2);
    gmsh::model::setPhysicalName(1, 2, "rest of boundary");
    if (opt.physical_surface) geo::addPhysicalGroup(2, {1}, 3);
    geo::synchronize();
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 1);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
    gmsh::option::setNumber("Mesh.ElementOrder", opt.element_order);
  });
}

/// The text with the first occurrence of `from` replaced by `to` (which must exist).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The case layer's mesh of msh text (the reader behind build_coarse_mesh).
Mesh mesh_of_msh_case(const std::string& text) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kMsh;
  spec.msh_text = text;
  return build_coarse_mesh(spec);
}

/// The detail of the CaseException reading the text gives, "" when it is accepted.
std::string error_of(const std::string& text) {
  try {
    mesh_of_msh_case(text);
  } catch (const CaseException& e) {
    EXPECT_EQ(e.errors().size(), 1u);
    EXPECT_EQ(e.errors().at(0).pointer, "/mesh/msh");
    EXPECT_FALSE(e.errors().at(0).detail.empty());
    return e.errors().at(0).detail;
  }
  return "";
}

#define EXPECT_MSH_ERROR(text, fragment)                                         \
  do {                                                                           \
    const std::string detail = error_of(text);                                   \
    EXPECT_NE(detail, "") << "accepted";                                         \
    EXPECT_NE(detail.find(fragment), std::string::npos) << "detail: " << detail; \
  } while (0)

class MshReader : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { valid_ = new std::string(square_msh()); }
  static void TearDownTestSuite() {
    delete valid_;
    valid_ = nullptr;
  }
  static const std::string& valid() { return *valid_; }
  /// Line holding the first node block header after $Nodes, e.g. "0 1 0 1".
  static std::string line_after(const std::string& marker) {
    const auto at = valid().find(marker);
    const auto start = valid().find('\n', at) + 1;
    return valid().substr(start, valid().find('\n', start) - start);
  }

 private:
  static inline std::string* valid_ = nullptr;
};

/// Two triangles of the unit square, its sides in physical curves 1–4, and `extra` more
/// physical names of dimension 1 (tags 10, 11, …) that no curve uses: the name of tag 10 + k
/// is "g" + (k % distinct), so names repeat once `extra` exceeds `distinct`.
std::string square_with_names(int extra, int distinct) {
  std::ostringstream out;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n"
      << extra + 4 << "\n"
      << "1 1 \"bottom\"\n1 2 \"right\"\n1 3 \"top\"\n1 4 \"left\"\n";
  for (int k = 0; k < extra; ++k) out << "1 " << 10 + k << " \"g" << k % distinct << "\"\n";
  out << "$EndPhysicalNames\n$Entities\n0 4 1 0\n1 0 0 0 1 0 0 1 1 0\n2 1 0 0 1 1 0 1 2 0\n"
         "3 0 1 0 1 1 0 1 3 0\n4 0 0 0 0 1 0 1 4 0\n1 0 0 0 1 1 0 0 4 1 2 3 4\n$EndEntities\n"
         "$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n"
         "$Elements\n5 6 1 6\n1 1 1 1\n1 1 2\n1 2 1 1\n2 2 3\n1 3 1 1\n3 3 4\n1 4 1 1\n4 4 1\n"
         "2 1 2 2\n5 1 2 3\n6 1 3 4\n$EndElements\n";
  return out.str();
}

TEST(MshReaderNames, EveryPhysicalNameIsOneGroupAndEqualNamesShareIt) {
  // 150 000 names, 50 000 of them distinct: each distinct name is one group, in the order of
  // its first tag, after the four sides (issue 50's probe had 190 000; the search for equal
  // names was quadratic in them).
  const Mesh m = mesh_from_msh(square_with_names(150000, 50000));
  ASSERT_EQ(m.group_names().size(), 4u + 50000u);
  EXPECT_EQ(m.group_names()[0], "bottom");
  EXPECT_EQ(m.group_names()[4], "g0");
  EXPECT_EQ(m.group_names()[4 + 49999], "g49999");
  for (int k : {0, 1, 777, 49999}) EXPECT_EQ(m.group_index("g" + std::to_string(k)), 4 + k);
  EXPECT_EQ(m.group_index("top"), 2);
  EXPECT_EQ(m.group_index("g50000"), -1);
  EXPECT_EQ(m.group_index(""), -1);
  int on_sides = 0;  // the sides' edges keep their groups
  for (int e = 0; e < m.num_edges(); ++e) on_sides += m.is_boundary_edge(e) && m.edge_group(e) < 4;
  EXPECT_EQ(on_sides, 4);
}

TEST_F(MshReader, ReadsTheSquareWrittenByGmsh) {
  const Mesh m = mesh_from_msh(valid());
  ASSERT_EQ(m.group_names(), (std::vector<std::string>{"bottom", "rest of boundary"}));
  double area = 0.0;
  for (int t = 0; t < m.num_triangles(); ++t) area += m.triangle_area(t);
  EXPECT_NEAR(area, 1.0, 1e-12);
  double bottom = 0.0, rest = 0.0;
  for (int e = 0; e < m.num_edges(); ++e) {
    if (m.edge_group(e) == 0) {
      bottom += m.edge_length(e);
      EXPECT_EQ(m.edge_midpoint(e).y(), 0.0);
    }
    if (m.edge_group(e) == 1) rest += m.edge_length(e);
  }
  EXPECT_NEAR(bottom, 1.0, 1e-12);
  EXPECT_NEAR(rest, 3.0, 1e-12);
  // Only triangle nodes become vertices; gmsh's point elements add none.
  EXPECT_EQ(m.num_vertices(), static_cast<int>(m.vertices().size()));

  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kMsh;
  spec.msh_text = valid();
  EXPECT_EQ(build_coarse_mesh(spec).num_triangles(), m.num_triangles());
}

TEST_F(MshReader, ToleratesWindowsLineEndsAndBlankLines) {
  std::string crlf;
  for (char c : valid()) {
    if (c == '\n')
      crlf += "\r\n\n";
    else
      crlf += c;
  }
  EXPECT_EQ(mesh_from_msh(crlf).num_triangles(), mesh_from_msh(valid()).num_triangles());
}

TEST_F(MshReader, RejectsEmptyText) {
  EXPECT_MSH_ERROR("", "empty");
  EXPECT_MSH_ERROR(" \n\t\n", "empty");
}

TEST_F(MshReader, RejectsTextThatIsNotMsh) {
  EXPECT_MSH_ERROR("hello world\n", "line 1: expected $MeshFormat");
}

TEST_F(MshReader, RejectsOtherVersions) {
  EXPECT_MSH_ERROR(replaced(valid(), "4.1 0 8", "2.2 0 8"), "only version 4.1");
  EXPECT_MSH_ERROR(replaced(valid(), "4.1 0 8", "4 0 8"), "line 2");
}

TEST_F(MshReader, RejectsBinaryMsh) {
  EXPECT_MSH_ERROR(replaced(valid(), "4.1 0 8", "4.1 1 8"), "binary");
}

TEST_F(MshReader, RejectsTruncatedNodes) {
  const std::string cut = valid().substr(0, valid().find("$EndNodes") - 20);
  EXPECT_MSH_ERROR(cut, "truncated");
  const auto nodes = valid().find("$Nodes");
  EXPECT_MSH_ERROR(valid().substr(0, nodes + 7), "expected the node counts");
  // A section that stops early runs into the next header.
  const std::string header = line_after("$Nodes\n");
  std::istringstream in(header);
  long long blocks, count, lo, hi;
  in >> blocks >> count >> lo >> hi;
  EXPECT_MSH_ERROR(replaced(valid(), header,
                            std::to_string(blocks + 1) + " " + std::to_string(count + 1) + " " +
                                std::to_string(lo) + " " + std::to_string(hi + 1)),
                   "expected a node block header");
}

TEST_F(MshReader, RejectsElementsReferringToMissingNodes) {
  const auto block = valid().find("\n2 1 2 ");
  ASSERT_NE(block, std::string::npos);
  const auto first = valid().find('\n', block + 1) + 1;
  const std::string line = valid().substr(first, valid().find('\n', first) - first);
  std::istringstream in(line);
  std::string tag, a, b, c;
  in >> tag >> a >> b >> c;
  EXPECT_MSH_ERROR(
      replaced(valid(), "\n" + line + "\n", "\n" + tag + " " + a + " " + b + " 99999\n"),
      "node '99999', which is not in $Nodes");
  EXPECT_MSH_ERROR(replaced(valid(), "\n" + line + "\n", "\n" + tag + " " + a + " " + b + "\n"),
                   "a triangle");
}

TEST_F(MshReader, RejectsBadNumbers) {
  EXPECT_MSH_ERROR(replaced(valid(), "\n1 0 0\n", "\n1 abc 0\n"),
                   "expected the y coordinate (a finite number), found 'abc'");
  EXPECT_MSH_ERROR(replaced(valid(), "\n1 0 0\n", "\n1 nan 0\n"), "finite number");
  EXPECT_MSH_ERROR(replaced(valid(), "\n1 0 0\n", "\n1 1e999 0\n"), "finite number");
  EXPECT_MSH_ERROR(replaced(valid(), "$Elements\n", "$Elements\nx"), "(an integer)");
  const std::string header = line_after("$Nodes\n");
  EXPECT_MSH_ERROR(replaced(valid(), "$Nodes\n" + header, "$Nodes\n1 -5 1 2"), "not negative");
}

TEST_F(MshReader, RejectsMissingEndElements) {
  EXPECT_MSH_ERROR(replaced(valid(), "$EndElements", ""), "without $EndElements");
  EXPECT_MSH_ERROR(replaced(valid(), "$EndPhysicalNames", ""), "expected $EndPhysicalNames");
  EXPECT_MSH_ERROR(replaced(valid(), "$Elements", "$Elementz"), "never closed");
}

TEST_F(MshReader, RejectsMeshesWithoutTriangles) {
  EXPECT_MSH_ERROR(square_msh({.physical_surface = false}), "no triangles");
  const auto nodes = valid().find("$Nodes");
  EXPECT_MSH_ERROR(valid().substr(0, nodes), "no $Nodes");
}

TEST_F(MshReader, RejectsHugeCountsWithoutAllocating) {
  const std::string header = line_after("$Nodes\n");
  EXPECT_MSH_ERROR(replaced(valid(), "$Nodes\n" + header, "$Nodes\n1 999999999999 1 999999999999"),
                   "more than the remaining");
  EXPECT_MSH_ERROR(replaced(valid(), "$Nodes\n" + header, "$Nodes\n1 99999999999999999999999 1 2"),
                   "(an integer)");
  EXPECT_MSH_ERROR(replaced(valid(), "$PhysicalNames\n2", "$PhysicalNames\n2000000000"),
                   "more than the remaining");
  const std::string elements = line_after("$Elements\n");
  EXPECT_MSH_ERROR(replaced(valid(), "$Elements\n" + elements, "$Elements\n4000000000 1 1 1"),
                   "more than the remaining");
}

TEST_F(MshReader, RejectsSecondOrderAndQuadrangles) {
  EXPECT_MSH_ERROR(square_msh({.element_order = 2}), "second-order");
  const auto block = valid().find("\n2 1 2 ");
  ASSERT_NE(block, std::string::npos);
  EXPECT_MSH_ERROR(replaced(valid(), "\n2 1 2 ", "\n2 1 3 "), "quadrangles");
}

TEST_F(MshReader, RejectsBoundaryOutsidePhysicalCurves) {
  EXPECT_MSH_ERROR(square_msh({.all_curves_physical = false}),
                   "put every boundary curve in a physical group");
}

TEST_F(MshReader, RejectsNodesOffThePlane) {
  EXPECT_MSH_ERROR(replaced(valid(), "\n1 1 0\n", "\n1 1 0.5\n"), "z = 0");
}

TEST_F(MshReader, EveryTruncationFailsCleanly) {
  const std::string& text = valid();
  for (std::size_t n = 0; n < text.size(); n += 7) {
    const std::string cut = text.substr(0, n);
    if (cut.find("$EndElements") != std::string::npos) continue;
    EXPECT_NE(error_of(cut), "") << "prefix of " << n << " bytes was accepted";
  }
}

TEST_F(MshReader, RandomCorruptionNeverCrashes) {
  std::mt19937 rng(12345);
  const std::string junk = "$0123456789 .-e\n\"xyz+";
  int rejected = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string text = valid();
    for (int k = 0; k < 3; ++k) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0:
          text[at] = junk[rng() % junk.size()];
          break;
        case 1:
          text.erase(at, 1 + rng() % 10);
          break;
        default:
          text.insert(at, 1, junk[rng() % junk.size()]);
      }
    }
    // Either a valid mesh or a CaseException; anything else fails the test.
    try {
      mesh_of_msh_case(text);
    } catch (const CaseException& e) {
      ++rejected;
      EXPECT_EQ(e.errors().at(0).pointer, "/mesh/msh");
    }
  }
  EXPECT_GT(rejected, 100);
}

}  // namespace
}  // namespace fosls
