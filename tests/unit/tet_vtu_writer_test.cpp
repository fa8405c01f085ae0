// The 3D .vtu file: a linear displacement field (which P1 × RT0 represents exactly) comes back
// as its exact displacements, stress and von Mises stress; on the Signorini block the contact
// arrays mark the contact vertices and their pressure; the binary file holds the same arrays.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "../tet_problems.hpp"
#include "post/tet_vtu_writer.hpp"

namespace fosls {
namespace {

/// The values of the ASCII DataArray called `name`.
std::vector<double> ascii_array(const std::string& vtu, const std::string& name) {
  const std::size_t at = vtu.find("Name=\"" + name + "\"");
  EXPECT_NE(at, std::string::npos) << name;
  if (at == std::string::npos) return {};
  const std::size_t begin = vtu.find('>', at) + 1, end = vtu.find("</DataArray>", at);
  std::istringstream in(vtu.substr(begin, end - begin));
  std::vector<double> values;
  for (double v; in >> v;) values.push_back(v);
  return values;
}

/// The names of the file's arrays, in order.
std::vector<std::string> array_names(const std::string& vtu) {
  std::vector<std::string> names;
  for (std::size_t at = vtu.find("Name=\""); at != std::string::npos;
       at = vtu.find("Name=\"", at + 1)) {
    const std::size_t begin = at + 6;
    names.push_back(vtu.substr(begin, vtu.find('"', begin) - begin));
  }
  return names;
}

Vector solved(const TetDiscretization& disc) {
  Vector x = Vector::Zero(disc.problem().qp.size());
  SolverOptions options;
  options.tolerance = 1e-12;
  solve_box_qp(disc.problem().qp, disc.build_level_hierarchy(), options, {}, x);
  return disc.assembler().full_vector(disc.problem(), x);
}

TEST(TetVtuWriter, ALinearFieldComesBackExactly) {
  const Eigen::Vector3d strain(0.01, -0.02, 0.03);  // u = (0.01 x, −0.02 y, 0.03 z)
  ProblemData<3> d;
  d.material = {.mu = 1.5, .lambda = 2.0};
  d.groups.resize(6);
  for (auto& g : d.groups) {
    g.role = GroupRole::kDirichlet;
    for (int c = 0; c < 3; ++c)
      g.values[c] = testing::of_point([c, strain](const Point3& x) { return strain[c] * x[c]; });
  }
  const TetDiscretization disc(build_tet_hierarchy(make_box({2, 2, 2}), 1), std::move(d));
  const std::string vtu =
      write_tet_vtu(disc.assembler(), disc.problem(), solved(disc), VtuEncoding::kAscii);
  const TetMesh& mesh = disc.meshes().finest();
  EXPECT_NE(vtu.find("NumberOfPoints=\"" + std::to_string(mesh.num_vertices()) + "\""),
            std::string::npos);
  EXPECT_NE(vtu.find("NumberOfCells=\"" + std::to_string(mesh.num_tets()) + "\""),
            std::string::npos);
  const std::vector<double> types = ascii_array(vtu, "types");
  ASSERT_EQ(types.size(), static_cast<std::size_t>(mesh.num_tets()));
  for (double t : types) EXPECT_EQ(t, 10.0);  // VTK_TETRA
  const std::vector<double> u = ascii_array(vtu, "u");
  ASSERT_EQ(u.size(), 3u * mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(u[3 * v + c], strain[c] * mesh.vertex(v)[c], 1e-9);
  // σ = λ tr ε I + 2μ ε, the same in every tetrahedron.
  const double trace = strain.sum();
  Eigen::Matrix3d sigma = (2.0 * trace) * Eigen::Matrix3d::Identity();
  sigma.diagonal() += 3.0 * strain;
  const Eigen::Matrix3d dev = sigma - sigma.trace() / 3.0 * Eigen::Matrix3d::Identity();
  const double mises = std::sqrt(1.5 * dev.squaredNorm());
  const std::vector<double> s = ascii_array(vtu, "sigma"), vm = ascii_array(vtu, "von_mises");
  ASSERT_EQ(s.size(), 9u * mesh.num_tets());
  for (int t = 0; t < mesh.num_tets(); ++t) {
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(s[9 * t + k], sigma(k / 3, k % 3), 1e-9) << t;
    EXPECT_NEAR(vm[t], mises, 1e-9);
  }
  for (double p : ascii_array(vtu, "contact_pressure")) EXPECT_EQ(p, 0.0);
  for (double j : ascii_array(vtu, "functional")) EXPECT_NEAR(j, 0.0, 1e-12);
}

TEST(TetVtuWriter, ContactArraysAndTheBinaryFile) {
  const TetDiscretization disc(build_tet_hierarchy(make_box({2, 2, 2}), 1),
                               testing::signorini_block(1.0));
  const Vector x = solved(disc);
  const std::string vtu = write_tet_vtu(disc.assembler(), disc.problem(), x, VtuEncoding::kAscii);
  const TetMesh& mesh = disc.meshes().finest();
  const std::vector<double> on = ascii_array(vtu, "contact_boundary"),
                            p = ascii_array(vtu, "contact_pressure");
  int contact = 0, loaded = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const bool bottom = mesh.vertex(v).z() == 0.0;
    EXPECT_EQ(on[v], bottom ? 1.0 : 0.0) << v;
    EXPECT_GE(p[v], bottom ? -1e-12 : 0.0);
    if (!bottom) EXPECT_EQ(p[v], 0.0);
    contact += bottom;
    loaded += p[v] > 0;
  }
  EXPECT_EQ(contact, 25);  // the bottom's 5 × 5 vertices
  EXPECT_GT(loaded, 0);
  const std::string binary = write_tet_vtu(disc.assembler(), disc.problem(), x);
  EXPECT_EQ(array_names(binary), array_names(vtu));
  std::vector<std::string> described;
  for (const VtuArray& a : tet_vtu_arrays()) described.push_back(a.name);
  std::vector<std::string> names = array_names(vtu);
  names.erase(names.begin(), names.begin() + 3);  // connectivity, offsets, types
  EXPECT_EQ(names, described);
}

}  // namespace
}  // namespace fosls
