#include "assembly/tet_hierarchy.hpp"

#include "fem/tet_element.hpp"

namespace fosls {

Eigen::SparseMatrix<double> tet_prolongation(const TetMesh& coarse, const TetMesh& fine,
                                             const TetRefinementMaps& maps) {
  const int ncv = coarse.num_vertices(), nfv = fine.num_vertices();
  auto sc = [ncv](int f, int i) { return 3 * ncv + 3 * f + i; };
  auto sf = [nfv](int f, int i) { return 3 * nfv + 3 * f + i; };
  std::vector<Eigen::Triplet<double>> t;
  for (int v = 0; v < nfv; ++v)
    for (int c = 0; c < 3; ++c) {
      if (v < ncv) {
        t.emplace_back(3 * v + c, 3 * v + c, 1.0);
      } else {
        for (int end : maps.midpoint_ends[v - ncv]) t.emplace_back(3 * v + c, 3 * end + c, 0.5);
      }
    }
  for (int f = 0; f < fine.num_faces(); ++f) {
    if (const int parent = maps.parent_face[f]; parent >= 0) {
      // RT0's normal component is constant on a face: a quarter carries a quarter of the flux.
      const double share =
          0.25 * (fine.face_normal(f).dot(coarse.face_normal(parent)) > 0 ? 1 : -1);
      for (int i = 0; i < 3; ++i) t.emplace_back(sf(f, i), sc(parent, i), share);
      continue;
    }
    const int tc = maps.parent_tet_of_face[f];
    const TetElement e(coarse, tc);
    const Point3 scaled_normal = fine.face_area(f) * fine.face_normal(f);
    for (int k = 0; k < 4; ++k) {
      // ψ_k is linear: its flux through a plane face is its value at the centroid times |f| n_f.
      const double flux = e.rt0(k, fine.face_centroid(f)).dot(scaled_normal);
      for (int i = 0; i < 3; ++i) t.emplace_back(sf(f, i), sc(coarse.tet_face(tc, k), i), flux);
    }
  }
  Eigen::SparseMatrix<double> p(3 * nfv + 3 * fine.num_faces(), 3 * ncv + 3 * coarse.num_faces());
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

std::vector<std::vector<int>> tet_vertex_patches(const TetSpace& space) {
  const auto faces = space.mesh().vertex_faces();
  std::vector<std::vector<int>> patches;
  for (int v = 0; v < space.mesh().num_vertices(); ++v) {
    std::vector<int> p;
    auto take = [&](int dof) {
      if (const int f = space.free_index(dof); f >= 0) p.push_back(f);
    };
    for (int c = 0; c < 3; ++c) take(space.u_dof(v, c));
    for (int f : faces[v])
      for (int i = 0; i < 3; ++i) take(space.sigma_dof(f, i));
    if (!p.empty()) patches.push_back(std::move(p));
  }
  return patches;
}

TetDiscretization::TetDiscretization(TetHierarchy meshes, TetProblemData data)
    : meshes_(std::move(meshes)), data_(std::move(data)) {
  for (const TetMesh& m : meshes_.meshes)
    spaces_.push_back(std::make_unique<TetSpace>(m, data_.roles()));
  assembler_ = std::make_unique<TetAssembler>(*spaces_.back(), data_);
  problem_ = assembler_->assemble_system();
}

LevelHierarchy TetDiscretization::build_level_hierarchy() const {
  LevelHierarchy h;
  h.levels.resize(meshes_.num_levels());
  for (int j = 0; j < meshes_.num_levels(); ++j) {
    const TetSpace& fine = *spaces_[j];
    Level& level = h.levels[j];
    level.num_dofs = fine.num_free();
    level.patches = tet_vertex_patches(fine);
    level.patch_split = {0, 0};  // one thread: every patch in the sequential part
    if (j == 0) continue;
    const TetSpace& coarse = *spaces_[j - 1];
    const Eigen::SparseMatrix<double> full =
        tet_prolongation(coarse.mesh(), fine.mesh(), meshes_.maps[j]);
    std::vector<Eigen::Triplet<double>> t;
    for (int col = 0; col < full.outerSize(); ++col) {
      const int fc = coarse.free_index(col);
      if (fc < 0) continue;
      for (Eigen::SparseMatrix<double>::InnerIterator it(full, col); it; ++it)
        if (const int fr = fine.free_index(static_cast<int>(it.row())); fr >= 0)
          t.emplace_back(fr, fc, it.value());
    }
    level.prolongation.resize(fine.num_free(), coarse.num_free());
    level.prolongation.setFromTriplets(t.begin(), t.end());
  }
  return h;
}

}  // namespace fosls
