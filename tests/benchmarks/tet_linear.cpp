// Benchmark (not a test): three dimensions, stage 1 (docs/method.md §11) — the multilevel
// method on 3D linear elasticity in FOSLS, per level of a refined box: unknowns, iterations,
// times and peak memory, for λ = 1 and λ = ∞ (the manufactured problem of
// tests/verification/tet_convergence_test.cpp: f = 2π² u, u = (sin πy sin πz, …), Dirichlet on
// three sides of the unit cube, Neumann on the other three).
//
//   build/bin/fosls-bench-3d --header
//   for l in 1 inf; do for r in 1 2 3 4; do build/bin/fosls-bench-3d $l $r; done; done
//
// One process per row, so that its peak memory is that row's. With a third argument `contact`
// (and optionally `pdas`, or `nostrip` for mmg without the contact-strip solves) the problem is the
// 3D Signorini block of tests/solver/tet_contact_test.cpp instead (stage 2), solved to a relative
// KKT residual of 1e-8.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "../tet_problems.hpp"
#include "assembly/tet_hierarchy.hpp"
#include "core/peak_memory.hpp"
#include "solvers/solve_loop.hpp"

namespace {

using namespace fosls;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Point3 u(const Point3& p) {
  const double x = M_PI * p.x(), y = M_PI * p.y(), z = M_PI * p.z();
  return {std::sin(y) * std::sin(z), std::sin(z) * std::sin(x), std::sin(x) * std::sin(y)};
}

TetProblemData problem(double lambda) {
  TetProblemData d;
  d.material = {.mu = 1.0, .lambda = lambda};
  for (int i = 0; i < 3; ++i)
    d.body_force[i] = [i](const Point3& x) { return 2.0 * M_PI * M_PI * u(x)[i]; };
  d.groups.resize(6);  // Neumann data are not needed for a table of solver costs: t = 0
  for (int g = 0; g < 6; g += 2) {
    d.groups[g].role = GroupRole::kDirichlet;
    for (int i = 0; i < 3; ++i) d.groups[g].values[i] = [i](const Point3& x) { return u(x)[i]; };
  }
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--header") {
    std::printf(
        "| λ | refinements | tetrahedra | unknowns | mmg iterations | assembly | solve | "
        "peak memory |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
    return 0;
  }
  if (argc < 3 || argc > 5) {
    std::fprintf(stderr,
                 "usage: fosls-bench-3d --header | fosls-bench-3d LAMBDA REFINEMENTS [contact "
                 "[pdas|nostrip]]\n");
    return 2;
  }
  const bool contact = argc >= 4 && std::string(argv[3]) == "contact";
  const bool pdas = argc == 5 && std::string(argv[4]) == "pdas";
  const bool no_strip = argc == 5 && std::string(argv[4]) == "nostrip";
  const double lambda =
      std::string(argv[1]) == "inf" ? std::numeric_limits<double>::infinity() : std::atof(argv[1]);
  const int r = std::atoi(argv[2]);
  const auto t0 = Clock::now();
  const TetDiscretization disc(build_tet_hierarchy(make_box({2, 2, 2}), r),
                               contact ? testing::signorini_block(lambda) : problem(lambda));
  const double assembly_s = seconds_since(t0);
  const auto t1 = Clock::now();
  Vector x = Vector::Zero(disc.problem().qp.size());
  SolverOptions options;
  if (pdas) options.method = SolverMethod::kPdas;
  options.multilevel.strip = !no_strip;
  const SolverReport report = solve_box_qp(
      disc.problem().qp, pdas ? LevelHierarchy{} : disc.build_level_hierarchy(), options, {}, x);
  const TetAssembler& a = disc.assembler();
  const double force = a.contact_force(a.full_vector(disc.problem(), x)).z();
  std::printf("| %s | %d | %d | %d | %s %d%s | %.2f s | %.2f s | %.0f MiB |", argv[1], r,
              disc.meshes().finest().num_tets(), disc.problem().qp.size(), pdas ? "pdas" : "mmg",
              report.iterations, report.converged ? "" : " (NOT converged)", assembly_s,
              seconds_since(t1), peak_rss_mib());
  if (contact)
    std::printf(
        " F_z = %.8f | galerkin %.2f s, smoothing %.2f s, strip %.2f s, coarse %.2f s, "
        "set-up %.2f s |",
        force, report.cycle.galerkin_s, report.cycle.smoothing_s, report.cycle.strip_s,
        report.cycle.coarse_s, report.setup_s);
  std::printf("\n");
  return 0;
}
