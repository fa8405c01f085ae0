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
// KKT residual of 1e-8; with `hertz` the half ball of tests/solver/tet_hertz_test.cpp (its mesh
// and indentation set by cells=N grading=P delta=D; `quarter`: its quarter with symmetry rollers,
// forces printed for the whole ball), which also prints the force against 3D
// Hertz and the contact radius and peak pressure against Hertz's for that force. vtu=FILE
// writes the solution for ParaView (post/tet_vtu_writer.hpp).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>

#include "../tet_problems.hpp"
#include "assembly/tet_hierarchy.hpp"
#include "core/peak_memory.hpp"
#include "mesh/tet_half_ball.hpp"
#include "post/tet_vtu_writer.hpp"
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

ProblemData<3> problem(double lambda) {
  ProblemData<3> d;
  d.material = {.mu = 1.0, .lambda = lambda};
  for (int i = 0; i < 3; ++i)
    d.body_force[i] =
        testing::of_point([i](const Point3& x) { return 2.0 * M_PI * M_PI * u(x)[i]; });
  d.groups.resize(6);  // Neumann data are not needed for a table of solver costs: t = 0
  for (int g = 0; g < 6; g += 2) {
    d.groups[g].role = GroupRole::kDirichlet;
    for (int i = 0; i < 3; ++i)
      d.groups[g].values[i] = testing::of_point([i](const Point3& x) { return u(x)[i]; });
  }
  return d;
}

/// The words after LAMBDA REFINEMENTS.
struct Options {
  bool contact = false, hertz = false, pdas = false, no_strip = false;
  HalfBallSpec ball{.cells = 2, .grading = 3.0};
  double delta = 0.01;      ///< the Hertz problem's indentation
  double volumetric = 1.0;  ///< weights.c2_volumetric (v, docs/method.md §2)
  std::string vtu;          ///< where to write the solution for ParaView, if anywhere
};

bool parse_word(const std::string& w, Options& o) {
  if (w == "contact") return o.contact = true;
  if (w == "hertz") return o.hertz = true;
  if (w == "pdas") return o.pdas = true;
  if (w == "nostrip") return o.no_strip = true;
  if (w == "quarter") return o.ball.quarter = true;
  if (w.rfind("cells=", 0) == 0) return (o.ball.cells = std::atoi(w.c_str() + 6)) > 0;
  if (w.rfind("vtu=", 0) == 0) return !(o.vtu = w.substr(4)).empty();
  if (w.rfind("v=", 0) == 0) return (o.volumetric = std::atof(w.c_str() + 2)) > 0;
  if (w.rfind("delta=", 0) == 0) return (o.delta = std::atof(w.c_str() + 6)) > 0;
  if (w.rfind("grading=", 0) == 0) return (o.ball.grading = std::atof(w.c_str() + 8)) >= 1.0;
  return false;
}

TetDiscretization discretization(const Options& o, double lambda, int r) {
  ProblemData<3> p = o.hertz     ? testing::hertz_half_ball(lambda, o.delta)
                     : o.contact ? testing::signorini_block(lambda)
                                 : problem(lambda);
  p.weights.c2_volumetric = o.volumetric;
  if (o.hertz && o.ball.quarter) {  // rollers on the symmetry planes x = 0 and y = 0
    p.groups.resize(5);
    for (int c = 0; c < 2; ++c) {
      p.groups[3 + c].role = GroupRole::kDirichlet;
      p.groups[3 + c].prescribed = 1 << c;
    }
  }
  return TetDiscretization(
      build_tet_hierarchy(o.hertz ? make_half_ball(o.ball) : make_box({2, 2, 2}), r), p);
}

/// The half ball's contact radius and peak pressure: a from the pressure's second moment about
/// the axis (for Hertz's p0 √(1 − r²/a²), ∫p r² dA / ∫p dA = 2a²/5, so all faces count, not just
/// the outermost loaded one), p0 as the largest face pressure (a face mean: slightly low).
std::array<double, 2> contact_radius_and_peak(const TetDiscretization& disc, const Vector& full) {
  const TetMesh& mesh = disc.meshes().finest();
  const std::vector<double> p =
      contact_pressure(disc.finest_space(), full, disc.problem().stress_scale);
  double force = 0.0, moment = 0.0, peak = 0.0;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Point3 c = mesh.face_centroid(f);
    const double projected = std::abs(mesh.face_normal(f).z()) * mesh.face_area(f);
    force += p[f] * projected;
    moment += p[f] * projected * (c.x() * c.x() + c.y() * c.y());
    peak = std::max(peak, p[f]);
  }
  return {std::sqrt(2.5 * moment / force), peak};
}

/// The force through the faces of mesh group `group` on the finest level, −∫ σ n (the force the
/// body exerts there; μ = 1 in these problems, and σ's rows are Cartesian off the contact).
Point3 force_through_group(const TetDiscretization& disc, const Vector& full, int group) {
  const TetMesh& mesh = disc.meshes().finest();
  const FoslsSpace<3>& space = disc.assembler().space();
  Point3 force = Point3::Zero();
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary_face(f) && mesh.face_group(f) == group)
      force -= full.segment<3>(space.sigma_dof(f, 0));
  return force;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--header") {
    std::printf(
        "| λ | refinements | tetrahedra | unknowns | mmg iterations | assembly | solve | "
        "peak memory |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
    return 0;
  }
  Options o;
  bool usable = argc >= 3;
  for (int k = 3; k < argc && usable; ++k) usable = parse_word(argv[k], o);
  if (!usable) {
    std::fprintf(stderr,
                 "usage: fosls-bench-3d --header | fosls-bench-3d LAMBDA REFINEMENTS "
                 "[contact|hertz [cells=N] [grading=P] [delta=D] [quarter]] [v=V] [pdas|nostrip] "
                 "[vtu=FILE]\n");
    return 2;
  }
  const double lambda =
      std::string(argv[1]) == "inf" ? std::numeric_limits<double>::infinity() : std::atof(argv[1]);
  const int r = std::atoi(argv[2]);
  const auto t0 = Clock::now();
  const TetDiscretization disc = discretization(o, lambda, r);
  const double assembly_s = seconds_since(t0);
  const auto t1 = Clock::now();
  Vector x = Vector::Zero(disc.problem().qp.size());
  SolverOptions options;
  if (o.pdas) options.method = SolverMethod::kPdas;
  options.multilevel.strip = !o.no_strip;
  const SolverReport report = solve_box_qp(
      disc.problem().qp, o.pdas ? LevelHierarchy{} : disc.build_level_hierarchy(), options, {}, x);
  const FoslsAssembler<3>& a = disc.assembler();
  const Vector full = a.full_vector(disc.problem(), x);
  // The quarter ball's forces stand for the whole ball's: four times its z component.
  const double whole = o.ball.quarter ? 4.0 : 1.0;
  const Point3 force =
      whole * contact_force(disc.finest_space(), full, disc.problem().stress_scale);
  std::printf("| %s | %d | %d | %d | %s %d%s | %.2f s | %.2f s | %.0f MiB |", argv[1], r,
              disc.meshes().finest().num_tets(), disc.problem().qp.size(), o.pdas ? "pdas" : "mmg",
              report.iterations, report.converged ? "" : " (NOT converged)", assembly_s,
              seconds_since(t1), peak_rss_mib());
  if (o.hertz) {
    const auto [radius, peak] = contact_radius_and_peak(disc, full);
    const double hertz = testing::hertz_force_3d(lambda, o.delta);
    const double a_f = testing::hertz_radius_3d(lambda, force.z());
    const double p0_f = testing::hertz_peak_3d(lambda, force.z());
    std::printf(
        " F_z = %.7f | Hertz %.7f | error %+.2f %% | a_h %.4f, Hertz(F) %.4f, %+.2f %% | p0_h "
        "%.4f, Hertz(F) %.4f, %+.2f %% |",
        force.z(), hertz, 100.0 * (force.z() / hertz - 1.0), radius, a_f,
        100.0 * (radius / a_f - 1.0), peak, p0_f, 100.0 * (peak / p0_f - 1.0));
    std::printf(" through the top: F_z = %.7f |", whole * force_through_group(disc, full, 0).z());
  }
  if (o.contact || o.hertz)
    std::printf(
        " F_z = %.8f | galerkin %.2f s, smoothing %.2f s, strip %.2f s, coarse %.2f s, "
        "set-up %.2f s |",
        force.z(), report.cycle.galerkin_s, report.cycle.smoothing_s, report.cycle.strip_s,
        report.cycle.coarse_s, report.setup_s);
  std::printf("\n");
  if (!o.vtu.empty()) std::ofstream(o.vtu) << write_tet_vtu(a, disc.problem(), full);
  return 0;
}
