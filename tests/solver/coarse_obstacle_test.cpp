// The coarse obstacles of the multilevel cycle (project_defect, docs/method.md §4.3): every
// coarse correction below the projected bounds, prolongated, stays below the fine defects
// (feasibility), the projections are ordered c ≤ b ≤ a, and (a) is exact for a defect that
// is linear on the coarse edge. On constructed links along a straight contact boundary and at
// P1 points of two or three coarse vertices (the links across skipped levels), and on the links
// of assembled hierarchies, uniform and adapted with contact-zone levels skipped.
#include <gtest/gtest.h>

#include <random>

#include "adapted_hierarchy.hpp"
#include "contact_problems.hpp"
#include "solvers/multilevel_cycle.hpp"

namespace fosls {
namespace {

constexpr CoarseProjection kProjections[] = {CoarseProjection::kA, CoarseProjection::kB,
                                             CoarseProjection::kC};

/// A straight contact boundary of `edges` coarse edges, each halved. Coarse DOFs: U_n at the
/// coarse vertices 0..edges, then S_n per edge. Fine DOFs: U_n at the coarse vertices, at the
/// midpoints, then S_n per half edge. The first vertex is fixed (a Dirichlet corner) when
/// `fixed_start`. P is the exact embedding: U_n linear along the edge, S_n = w_k S_n(E).
Level straight_boundary(int edges, bool fixed_start, std::mt19937& rng) {
  std::uniform_real_distribution<double> weight(0.3, 0.7);
  const int nc = 2 * edges + 1, nf = (edges + 1) + edges + 2 * edges;
  auto coarse_un = [&](int v) { return (fixed_start && v == 0) ? -1 : v; };
  auto fine_un = [&](int v) { return (fixed_start && v == 0) ? -1 : v; };
  Level level;
  level.num_dofs = nf;
  std::vector<Eigen::Triplet<double>> p;
  for (int v = 0; v <= edges; ++v)
    if (coarse_un(v) >= 0) p.emplace_back(fine_un(v), coarse_un(v), 1.0);
  for (int e = 0; e < edges; ++e) {
    ContactLink l;
    l.coarse_un_a = coarse_un(e), l.coarse_un_b = coarse_un(e + 1);
    l.fine_un_a = fine_un(e), l.fine_un_b = fine_un(e + 1), l.fine_un_mid = edges + 1 + e;
    for (int end : {l.coarse_un_a, l.coarse_un_b})
      if (end >= 0) p.emplace_back(l.fine_un_mid, end, 0.5);
    l.coarse_sn = edges + 1 + e;
    for (int k = 0; k < 2; ++k) {
      l.fine_sn[k] = 2 * edges + 1 + 2 * e + k;
      l.sn_weight[k] = weight(rng);
      p.emplace_back(l.fine_sn[k], l.coarse_sn, l.sn_weight[k]);
    }
    level.links.push_back(l);
  }
  level.prolongation.resize(nf, nc);
  level.prolongation.setFromTriplets(p.begin(), p.end());
  return level;
}

/// U_n links of fine points that are P1 combinations of two or three of `vertices` coarse
/// vertices with dyadic weights (a chain of midpoints along a coarse edge, a point inside a
/// coarse face). Coarse DOFs: U_n at the coarse vertices; fine DOFs: U_n at the coarse vertices,
/// then at the points.
Level p1_points(int vertices, int points, std::mt19937& rng) {
  std::uniform_int_distribution<int> vertex(0, vertices - 1), ends(2, 3), eighths(1, 6);
  Level level;
  level.num_dofs = vertices + points;
  std::vector<Eigen::Triplet<double>> p;
  for (int v = 0; v < vertices; ++v) p.emplace_back(v, v, 1.0);
  for (int m = 0; m < points; ++m) {
    ContactLink l;
    const int n = ends(rng);
    std::array<int, 3> v = {vertex(rng), vertex(rng), vertex(rng)};
    while (v[1] == v[0]) v[1] = vertex(rng);
    while (v[2] == v[0] || v[2] == v[1]) v[2] = vertex(rng);
    const double first = eighths(rng) / 8.0;
    const double second = n == 2 ? 1.0 - first : (1.0 - first) * (eighths(rng) < 4 ? 0.25 : 0.5);
    l.un_weight = {first, second, n == 2 ? 0.0 : 1.0 - first - second};
    l.coarse_un_a = l.fine_un_a = v[0];
    l.coarse_un_b = l.fine_un_b = v[1];
    if (n == 3) l.coarse_un_c = l.fine_un_c = v[2];
    l.fine_un_mid = vertices + m;
    for (int i = 0; i < n; ++i) p.emplace_back(l.fine_un_mid, v[i], l.un_weight[i]);
    level.links.push_back(l);
  }
  level.prolongation.resize(level.num_dofs, vertices);
  level.prolongation.setFromTriplets(p.begin(), p.end());
  return level;
}

/// Fine defects d ≥ 0 at the bounded fine DOFs, kNoBound at a few (truncated or unbounded).
Vector random_defect(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vector d(n);
  for (int i = 0; i < n; ++i) {
    const double s = u(rng);
    d[i] = s < 0.1 ? kNoBound : s < 0.2 ? 0.0 : u(rng);
  }
  return d;
}

/// Every v ≤ coarse_hi on the coarse DOFs of `bounded` (zero on the others) gives P v ≤ d on
/// the fine DOFs with a finite defect: the corner v = coarse_hi, and random corrections below.
void expect_feasible(const SparseMatrix& p, const Vector& d, const Vector& coarse_hi,
                     const std::vector<char>& bounded, std::mt19937& rng, const char* what) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int sample = 0; sample < 50; ++sample) {
    Vector v(coarse_hi.size());
    for (int i = 0; i < v.size(); ++i) {
      if (!bounded[i])
        v[i] = 0.0;
      else if (!is_bounded_above(coarse_hi[i]))
        v[i] = 10.0 * (2.0 * u(rng) - 1.0);  // unconstrained: only unbounded fine DOFs see it
      else
        v[i] = coarse_hi[i] - (sample == 0 || u(rng) < 0.3 ? 0.0 : u(rng));
    }
    const Vector fine = p * v;
    for (int i = 0; i < d.size(); ++i)
      if (is_bounded_above(d[i])) {
        ASSERT_LE(fine[i], d[i] + 1e-14 * (1.0 + std::abs(d[i])))
            << what << ", sample " << sample << ", fine DOF " << i;
      }
  }
}

TEST(CoarseObstacle, ProlongatedCorrectionsStayBelowTheFineDefects) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const Level level = straight_boundary(1 + trial % 5, trial % 2 == 0, rng);
    const Vector d = random_defect(level.num_dofs, rng);
    const std::vector<char> bounded(level.prolongation.cols(), 1);
    for (CoarseProjection projection : kProjections) {
      Vector hi = Vector::Constant(level.prolongation.cols(), kNoBound);
      project_defect(level, projection, d, hi);
      for (int i = 0; i < hi.size(); ++i) ASSERT_GE(hi[i], 0.0);
      expect_feasible(level.prolongation, d, hi, bounded, rng, "constructed links");
    }
  }
}

TEST(CoarseObstacle, ProlongatedCorrectionsStayBelowTheDefectsAtP1PointsOfTwoOrThreeVertices) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const Level level = p1_points(3 + trial % 4, 1 + trial % 7, rng);
    Vector d = random_defect(level.num_dofs, rng);
    // A coarse vertex of no link is no contact vertex: unbounded on both levels.
    std::vector<char> bounded(level.prolongation.cols(), 0);
    for (const ContactLink& l : level.links)
      for (int v : {l.coarse_un_a, l.coarse_un_b, l.coarse_un_c})
        if (v >= 0) bounded[v] = 1;
    for (int v = 0; v < level.prolongation.cols(); ++v)
      if (!bounded[v]) d[v] = kNoBound;
    for (CoarseProjection projection : kProjections) {
      Vector hi = Vector::Constant(level.prolongation.cols(), kNoBound);
      project_defect(level, projection, d, hi);
      for (int i = 0; i < hi.size(); ++i) ASSERT_GE(hi[i], 0.0);
      expect_feasible(level.prolongation, d, hi, bounded, rng, "P1 points");
    }
  }
}

TEST(CoarseObstacle, ProjectionsAreOrderedCBelowBBelowA) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 200; ++trial) {
    const Level level = straight_boundary(1 + trial % 5, trial % 2 == 1, rng);
    const Vector d = random_defect(level.num_dofs, rng);
    Vector a = Vector::Constant(level.prolongation.cols(), kNoBound), b = a, c = a;
    project_defect(level, CoarseProjection::kA, d, a);
    project_defect(level, CoarseProjection::kB, d, b);
    project_defect(level, CoarseProjection::kC, d, c);
    for (int i = 0; i < a.size(); ++i) {
      EXPECT_LE(c[i], b[i]) << "trial " << trial << ", coarse DOF " << i;
      EXPECT_LE(b[i], a[i]) << "trial " << trial << ", coarse DOF " << i;
    }
  }
}

TEST(CoarseObstacle, LeastRestrictiveIsExactForALinearDefect) {
  // d linear along one coarse edge: (a) gives back its end values, (b) and (c) are stricter.
  std::mt19937 rng(1);
  const Level level = straight_boundary(1, false, rng);
  const ContactLink& l = level.links[0];
  Vector d = Vector::Constant(level.num_dofs, kNoBound);
  d[l.fine_un_a] = 0.2, d[l.fine_un_b] = 0.6, d[l.fine_un_mid] = 0.4;
  Vector a = Vector::Constant(3, kNoBound), b = a;
  project_defect(level, CoarseProjection::kA, d, a);
  project_defect(level, CoarseProjection::kB, d, b);
  EXPECT_DOUBLE_EQ(a[l.coarse_un_a], 0.2);
  EXPECT_DOUBLE_EQ(a[l.coarse_un_b], 0.6);
  EXPECT_DOUBLE_EQ(b[l.coarse_un_b], 0.4);
}

/// No prolongated correction below the projected obstacles of `h`'s links leaves K.
void expect_feasible_links(const LevelHierarchy& h, std::mt19937& rng) {
  for (int j = 1; j < h.num_levels(); ++j) {
    const Level& level = h.levels[j];
    ASSERT_FALSE(level.links.empty());
    std::vector<char> bounded(level.prolongation.cols(), 0);
    for (const ContactLink& l : level.links)
      for (int i : {l.coarse_un_a, l.coarse_un_b, l.coarse_un_c, l.coarse_sn})
        if (i >= 0) bounded[i] = 1;
    std::vector<char> fine_bounded(level.num_dofs, 0);
    for (const ContactLink& l : level.links)
      for (int i :
           {l.fine_un_a, l.fine_un_mid, l.fine_un_b, l.fine_un_c, l.fine_sn[0], l.fine_sn[1]})
        if (i >= 0) fine_bounded[i] = 1;
    for (int trial = 0; trial < 20; ++trial) {
      Vector d = random_defect(level.num_dofs, rng);
      for (int i = 0; i < d.size(); ++i)
        if (!fine_bounded[i]) d[i] = kNoBound;
      for (CoarseProjection projection : kProjections) {
        Vector hi = Vector::Constant(level.prolongation.cols(), kNoBound);
        project_defect(level, projection, d, hi);
        expect_feasible(level.prolongation, d, hi, bounded, rng, "assembled links");
      }
    }
  }
}

TEST(CoarseObstacle, FeasibleOnTheLinksOfAnAssembledHierarchy) {
  // The square's contact boundary is straight, so the contact normals agree between levels
  // and the projected obstacles are exact: no prolongated correction may leave K.
  const Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.25}), 2),
                               testing::signorini_square(1.0));
  std::mt19937 rng(2);
  expect_feasible_links(disc.build_level_hierarchy(), rng);
}

TEST(CoarseObstacle, FeasibleWhereTheContactZonesLevelsAreSkipped) {
  // An adapted square whose contact zone is bisected in consecutive steps: the solver levels
  // skip them, and the links hold chains of midpoints (weights other than ½) and facets of more
  // than two children (partners).
  const ProblemData<2> data = testing::signorini_square(1.0);
  const Discretization<2> disc(
      testing::adapted_hierarchy(build_mesh_hierarchy(make_square({.size = 0.25}), 1), data, 6),
      data);
  const LevelHierarchy h = disc.build_level_hierarchy();
  int chains = 0, grouped = 0;
  for (const Level& level : h.levels)
    for (const ContactLink& l : level.links) {
      chains += l.fine_un_mid >= 0 && l.un_weight[0] != 0.5;
      grouped += !l.partners.empty();
    }
  std::printf("%d solver levels of %d, %d chain points, %d grouped links\n", h.num_levels(),
              disc.num_levels(), chains, grouped);
  EXPECT_GT(chains, 0);
  EXPECT_GT(grouped, 0);
  std::mt19937 rng(3);
  expect_feasible_links(h, rng);
}

}  // namespace
}  // namespace fosls
