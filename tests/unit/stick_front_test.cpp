// The stick zone's fronts located within their edges (post/stick_front.hpp), on synthetic slip
// profiles along a line of contact edges with a known stick zone [c1, c2].
#include "post/stick_front.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace fosls {
namespace {

using State = ContactEdgeResult::State;

/// Edges between the vertices x (increasing), all in contact, with the slip of the step
/// slip(x) at their vertices and the state the result gives them (stick: zero at both).
std::vector<ContactEdgeResult> edges_on_line(const std::vector<double>& x,
                                             const std::function<double(double)>& slip) {
  std::vector<ContactEdgeResult> edges;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    ContactEdgeResult r;
    r.edge = static_cast<int>(k);
    r.length = x[k + 1] - x[k];
    r.s = 0.5 * (x[k] + x[k + 1]);
    r.active = true;
    r.ends = {static_cast<int>(k), static_cast<int>(k + 1)};
    r.end_slip = {slip(x[k]), slip(x[k + 1])};
    r.state = r.end_slip[0] == 0.0 && r.end_slip[1] == 0.0 ? State::kStick : State::kSlip;
    edges.push_back(r);
  }
  return edges;
}

/// Vertices on [0, 1] with lengths that vary from edge to edge (no front on a vertex).
std::vector<double> uneven_vertices(int n) {
  std::vector<double> x;
  for (int k = 0; k <= n; ++k) x.push_back((k + 0.3 * std::sin(2.0 * k)) / n);
  x.front() = 0.0, x.back() = 1.0;
  return x;
}

/// Cattaneo–Mindlin's slip near its fronts: k d^(3/2) beyond them, of either sign.
double power_slip(double x, double c1, double c2, double power) {
  if (x < c1) return 0.02 * std::pow(c1 - x, power);
  if (x > c2) return -0.05 * std::pow(x - c2, power);
  return 0.0;
}

/// The whole-edge stick zone [s_start, s_end] of `edges`.
std::pair<double, double> whole_edges(const std::vector<ContactEdgeResult>& edges) {
  ContactResult result;
  result.edges = edges;
  const ContactZone z = result.stick_zone();
  return {z.s_start, z.s_end};
}

TEST(StickFront, ASlipGrowingLikeThePowerThreeHalvesGivesItsFrontExactly) {
  const double c1 = 0.3141, c2 = 0.7777;
  const auto edges =
      edges_on_line(uneven_vertices(40), [&](double x) { return power_slip(x, c1, c2, 1.5); });
  const auto [start, end] = whole_edges(edges);
  const StickFronts fronts = locate_stick_fronts(edges);
  // The whole-edge zone lies inside the true one by up to an edge at each end.
  EXPECT_GT(start, c1 + 1e-3);
  EXPECT_LT(end, c2 - 1e-3);
  EXPECT_NEAR(fronts.start, c1, 1e-12);
  EXPECT_NEAR(fronts.end, c2, 1e-12);
  EXPECT_NEAR(fronts.width, c2 - c1, 1e-12);
}

// With a slip of another power the fit is not exact (power 2 lands on the other side of the
// front from the whole-edge end), but it never leaves the edges that hold the fronts.
TEST(StickFront, AnotherPowerStaysWithinTheEdgesHoldingTheFronts) {
  const auto x = uneven_vertices(40);
  for (double power : {1.0, 2.0, 2.5}) {
    const double c1 = 0.2718, c2 = 0.6931;
    const auto edges = edges_on_line(x, [&](double v) { return power_slip(v, c1, c2, power); });
    const auto [start, end] = whole_edges(edges);
    const StickFronts fronts = locate_stick_fronts(edges);
    const double h = 1.6 / 40;  // longer than the longest edge
    EXPECT_LE(fronts.start, start) << power;
    EXPECT_GE(fronts.start, start - h) << power;
    EXPECT_GE(fronts.end, end) << power;
    EXPECT_LE(fronts.end, end + h) << power;
  }
}

TEST(StickFront, WithoutASlipGrowingAwayTheFrontIsTheWholeEdgeEnd) {
  // Constant slip beyond the stick zone, and a stick zone reaching an open edge.
  auto edges = edges_on_line(uneven_vertices(20), [](double v) { return v < 0.4 ? 1e-3 : 0.0; });
  edges.back().active = false;
  edges.back().state = State::kOpen;
  const auto [start, end] = whole_edges(edges);
  const StickFronts fronts = locate_stick_fronts(edges);
  EXPECT_EQ(fronts.start, start);
  EXPECT_EQ(fronts.end, end);
  EXPECT_DOUBLE_EQ(fronts.width, end - start);
}

TEST(StickFront, NoStickEdgeNoFront) {
  const auto edges = edges_on_line(uneven_vertices(10), [](double v) { return v + 1.0; });
  const StickFronts fronts = locate_stick_fronts(edges);
  EXPECT_EQ(fronts.width, 0.0);
}

TEST(StickFront, TheOffsetIsTheZeroOfTheLineThroughSlipToTheTwoThirds) {
  // slip = d^(3/2) from a front 0.25 before the first slipping vertex's edge start.
  const double f = 0.25, d1 = 1.0, d2 = 2.0;
  EXPECT_NEAR(stick_front_offset(d1, std::pow(d1 - f, 1.5), d2, std::pow(d2 - f, 1.5)), f, 1e-14);
  EXPECT_EQ(stick_front_offset(d1, 2.0, d2, 1.0), 0.0);     // falling away from the front
  EXPECT_EQ(stick_front_offset(d1, 1.0, d2, 1.0001), 0.0);  // the line's zero before the run
  EXPECT_EQ(stick_front_offset(d1, 0.0, d2, 1.0), d1);      // at the first slipping vertex
}

}  // namespace
}  // namespace fosls
