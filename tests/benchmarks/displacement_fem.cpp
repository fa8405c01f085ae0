// Benchmark and reference (not a test): an independent displacement finite element solution of
// a contact case — the method FOSLS is measured against (docs/validation.md §12).
//
//   build/bin/fosls-bench-displacement CASE.json [--element p1|mixed] [--axisymmetric]
//
// Both discretisations are nodal, on the case's mesh refined `mesh.refinements` times, and share
// nothing with the FOSLS discretisation but the mesh and the problem's data:
// - p1: continuous P1 displacement, the plain displacement FEM (finite λ only: it locks as λ → ∞);
// - mixed: P1 displacement on that mesh, continuous P1 pressure on the mesh one level coarser
//   (P1-iso-P2/P1, inf-sup stable): find (u, p) with 2μ (ε(u), ε(v)) + (p, div v) = ℓ(v) and
//   (div u, q) − (p, q)/λ = 0, so σ = 2μ ε(u) + p I; λ = ∞ is the incompressible limit.
// Frictionless contact: nodal constraints u·d ≤ g at the contact group's vertices, d and g as the
// case defines them (body normal by default; a plane obstacle or a gap function). Solved by the
// primal–dual active set method (a semismooth Newton method): each step replaces the rows of the
// active vertices by u·d = g and the tangential equilibrium, and solves with a sparse LU (UMFPACK),
// until the active set repeats. The contact force is the sum of the nodal contact forces.
// --axisymmetric: the mesh is the meridian section (x = r ≥ 0, y the axis) of a body of
// revolution, loaded and constrained symmetrically; the force is the whole body's (the 3D
// half ball's reference, docs/validation.md §16).
// Prints one JSON object.
#include <sys/resource.h>

#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "case/format/case_reader.hpp"
#include "case/format/expression.hpp"
#include "case/run/mesh_factory.hpp"
#include "displacement_elements.hpp"
#include "mesh/refinement.hpp"

namespace {

using namespace fosls;
using Clock = std::chrono::steady_clock;
using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
// 64-bit indices: UMFPACK's int version runs out of index space near a million unknowns.
using ColMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;
using Triplets = std::vector<Eigen::Triplet<double>>;
constexpr double kInf = std::numeric_limits<double>::infinity();

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double constant(const Scalar& s, const std::string& what) {
  if (!s.is_constant()) throw std::runtime_error(what + ": only constant values are supported");
  return s.value;
}

/// One contact vertex: u·d ≤ gap. On a roller (one component prescribed) only the other
/// component is free, and the constraint replaces its equation when active.
struct NodalConstraint {
  int vertex;
  Point d;
  double gap;
  int free_component = -1;  ///< -1: both free; 0 or 1: the one a roller leaves free
};

struct Options {
  bool mixed = false;
  bool axisymmetric = false;  ///< x is the radius, y the axis; forces of the whole body
};

/// The system before boundary conditions: displacement DOFs 2v, 2v + 1 of vertex v, then the
/// pressure DOFs (mixed only).
struct Assembled {
  RowMatrix K;
  Eigen::VectorXd f;
  int displacement_dofs = 0;
};

/// Pressure on the coarser level: a fine vertex that is a coarse vertex carries its basis
/// function, a midpoint the mean of its coarse edge's two.
std::vector<std::vector<std::pair<int, double>>> pressure_weights(const Mesh& coarse,
                                                                  const RefinementMaps& maps,
                                                                  int fine_vertices) {
  std::vector<std::vector<std::pair<int, double>>> w(fine_vertices);
  for (int v = 0; v < fine_vertices; ++v) {
    if (v < maps.num_coarse_vertices) {
      w[v] = {{v, 1.0}};
    } else {
      const auto& e = coarse.edge(maps.midpoint_edge[v - maps.num_coarse_vertices]);
      w[v] = {{e[0], 0.5}, {e[1], 0.5}};
    }
  }
  return w;
}

/// The system on level `level` of `meshes` (mixed: the pressure on level − 1).
Assembled assemble(const MeshHierarchy& meshes, int level, const CaseSpec& spec,
                   const Options& options) {
  const Mesh& mesh = meshes.meshes[level];
  const bool mixed = options.mixed;
  const double lambda = spec.material.lambda;
  const int nv = mesh.num_vertices();
  std::vector<std::vector<std::pair<int, double>>> pw;
  int np = 0;
  if (mixed) {
    const Mesh& coarse = meshes.meshes[level - 1];
    pw = pressure_weights(coarse, meshes.maps[level], nv);
    np = coarse.num_vertices();
  }
  Assembled out;
  out.displacement_dofs = 2 * nv;
  out.f = Eigen::VectorXd::Zero(2 * nv + np);
  ElementData data;
  data.mu = spec.material.mu;
  data.lambda_in_stiffness = mixed ? 0.0 : lambda;
  data.body_force =
      Point(constant(spec.body_force[0], "body_force"), constant(spec.body_force[1], "body_force"));
  Triplets t;
  t.reserve(static_cast<std::size_t>(mesh.num_triangles()) * (36 + (mixed ? 2 * 6 * 6 + 36 : 0)));
  for (int k = 0; k < mesh.num_triangles(); ++k) {
    const auto& tri = mesh.triangle(k);
    for (int i = 0; i < 3; ++i) data.x[i] = mesh.vertex(tri[i]);
    const ElementMatrices m =
        options.axisymmetric ? axisymmetric_element(data) : plane_strain_element(data);
    for (int i = 0; i < 6; ++i) {
      out.f[2 * tri[i / 2] + i % 2] += m.load[i];
      for (int j = 0; j < 6; ++j)
        t.emplace_back(2 * tri[i / 2] + i % 2, 2 * tri[j / 2] + j % 2, m.stiffness(i, j));
    }
    if (!mixed) continue;
    // (q, div v) and −(p, q)/λ, with q and p in the coarser level's P1 space.
    for (int i = 0; i < 3; ++i)
      for (const auto& [pdof, weight] : pw[tri[i]])
        for (int j = 0; j < 6; ++j) {
          const double value = weight * m.coupling(i, j);
          const int row = 2 * nv + pdof, col = 2 * tri[j / 2] + j % 2;
          t.emplace_back(row, col, value);
          t.emplace_back(col, row, value);
        }
    if (std::isinf(lambda)) continue;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (const auto& [pi, wi] : pw[tri[i]])
          for (const auto& [pj, wj] : pw[tri[j]])
            t.emplace_back(2 * nv + pi, 2 * nv + pj, -m.mass(i, j) * wi * wj / lambda);
  }
  out.K.resize(2 * nv + np, 2 * nv + np);
  out.K.setFromTriplets(t.begin(), t.end());
  return out;
}

/// Prescribed values of the Dirichlet DOFs (NaN: free), Neumann tractions added to f, and the
/// contact vertices' constraints.
struct BoundaryData {
  std::vector<double> prescribed;
  std::vector<NodalConstraint> contact;
};

BoundaryData boundary_data(const Mesh& mesh, const CaseSpec& spec, bool axisymmetric,
                           Eigen::VectorXd& f) {
  BoundaryData out;
  out.prescribed.assign(2 * mesh.num_vertices(), std::nan(""));
  std::vector<Point> normal_sum(mesh.num_vertices(), Point::Zero());
  std::vector<int> curve_of(mesh.num_vertices(), -1);
  std::vector<const BoundaryCondition*> contact_bc(mesh.num_vertices(), nullptr);
  std::map<const BoundaryCondition*, ScalarFunction> gap_of;  // compiled once per condition
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!mesh.is_boundary_edge(e)) continue;
    const std::string& group = mesh.group_names()[mesh.edge_group(e)];
    const auto found = spec.boundary.find(group);
    if (found == spec.boundary.end()) throw std::runtime_error("no condition for group " + group);
    const BoundaryCondition& bc = found->second;
    const auto& [v0, v1] = mesh.edge(e);
    switch (bc.type) {
      case BoundaryCondition::Type::kDirichlet:
        for (int k = 0; k < 2; ++k)
          if (bc.prescribed[k])
            out.prescribed[2 * v0 + k] = out.prescribed[2 * v1 + k] =
                constant(bc.values[k], group + " displacement");
        break;
      case BoundaryCondition::Type::kNeumann:
        for (int k = 0; k < 2; ++k) {
          const double t = constant(bc.values[k], group);
          const auto w = edge_load_weights(mesh.vertex(v0), mesh.vertex(v1), axisymmetric);
          f[2 * v0 + k] += w[0] * t;
          f[2 * v1 + k] += w[1] * t;
        }
        break;
      case BoundaryCondition::Type::kContact:
        if (bc.obstacle.kind == Obstacle::Kind::kBall)
          throw std::runtime_error(group + ": a circle obstacle is not supported here");
        if (bc.obstacle.kind == Obstacle::Kind::kGap && !gap_of.count(&bc))
          gap_of[&bc] = compile_scalar(bc.obstacle.gap);
        for (int v : {v0, v1}) {
          normal_sum[v] += mesh.edge_normal(e);
          if (mesh.edge_curve(e) >= 0) curve_of[v] = mesh.edge_curve(e);
          contact_bc[v] = &bc;
        }
        break;
      default:
        throw std::runtime_error(group + ": boundary type not supported here");
    }
  }
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const BoundaryCondition* bc = contact_bc[v];
    const bool x_free = std::isnan(out.prescribed[2 * v]);
    const bool y_free = std::isnan(out.prescribed[2 * v + 1]);
    if (!bc || (!x_free && !y_free)) continue;
    if (bc->direction == ContactDirection::kObstacleNormal)
      // FOSLS keeps the traction along the body normal with the constraint along the obstacle's
      // (method.md §1); a nodal constraint's reaction acts along its own direction.
      throw std::runtime_error("direction obstacle_normal is not supported here: use body_normal");
    const Point x = mesh.vertex(v);
    // The body normal at a vertex: the circle's where the boundary is an arc, else the mean of
    // the two edges'.
    Point n = normal_sum[v].normalized();
    if (curve_of[v] >= 0) {
      const Point radial = (x - mesh.curves()[curve_of[v]].center).normalized();
      n = radial.dot(n) > 0 ? radial : Point(-radial);
    }
    NodalConstraint c{v, n, 0.0};
    if (bc->obstacle.kind == Obstacle::Kind::kGap) {
      c.gap = gap_of.at(bc)(x.x(), x.y());  // given along the body normal
    } else {
      const Point nu =
          bc->obstacle.normal.head<2>().normalized();  // from the obstacle into the body
      const double approach = -n.dot(nu);
      if (approach <= 1e-12) continue;  // n never reaches the plane
      c.gap = (x - bc->obstacle.point.head<2>()).dot(nu) / approach;
    }
    if (!x_free || !y_free) {
      c.free_component = x_free ? 0 : 1;
      // Along the roller's own direction the roller already decides.
      if (std::abs(n[c.free_component]) < 1e-12) continue;
    }
    out.contact.push_back(c);
  }
  return out;
}

struct Solution {
  Eigen::VectorXd x;
  std::vector<double> contact_force;  ///< λ_i ≥ 0 per constraint: the force −λ_i d_i on the body
  int iterations = 0;
  std::vector<char> active_set;
  bool converged = false;
  double solve_s = 0.0;
};

/// The primal–dual active set iteration: active where λ_i + c_i (u·d − g) > 0, c_i the
/// diagonal of K at the vertex (so that force and gap are compared in one unit).
Solution solve_contact(const Assembled& sys, const BoundaryData& bd, std::vector<char> active) {
  const int n = static_cast<int>(sys.f.size());
  Solution s;
  s.contact_force.assign(bd.contact.size(), 0.0);
  std::vector<int> constraint_of(sys.displacement_dofs / 2, -1);
  for (std::size_t i = 0; i < bd.contact.size(); ++i) constraint_of[bd.contact[i].vertex] = i;
  const int kMaxIterations = 60;
  for (s.iterations = 1; s.iterations <= kMaxIterations; ++s.iterations) {
    Triplets t;
    t.reserve(sys.K.nonZeros() + n);
    Eigen::VectorXd rhs = sys.f;
    for (int row = 0; row < n; ++row) {
      if (row < sys.displacement_dofs && !std::isnan(bd.prescribed[row])) {
        t.emplace_back(row, row, 1.0);
        rhs[row] = bd.prescribed[row];
        continue;
      }
      const int c = row < sys.displacement_dofs ? constraint_of[row / 2] : -1;
      if (c < 0 || !active[c]) {
        for (RowMatrix::InnerIterator it(sys.K, row); it; ++it)
          t.emplace_back(row, it.col(), it.value());
        continue;
      }
      // Active vertex: its x row becomes u·d = g, its y row the equilibrium along the tangent;
      // on a roller (its prescribed row handled above) the free row becomes u·d = g.
      const NodalConstraint& con = bd.contact[c];
      const int vx = 2 * con.vertex;
      if (row == vx || con.free_component >= 0) {
        t.emplace_back(row, vx, con.d.x());
        t.emplace_back(row, vx + 1, con.d.y());
        rhs[row] = con.gap;
      } else {
        const Point tangent(-con.d.y(), con.d.x());
        for (int k = 0; k < 2; ++k)
          for (RowMatrix::InnerIterator it(sys.K, vx + k); it; ++it)
            t.emplace_back(row, it.col(), tangent[k] * it.value());
        rhs[row] = tangent.x() * sys.f[vx] + tangent.y() * sys.f[vx + 1];
      }
    }
    ColMatrix m(n, n);
    m.setFromTriplets(t.begin(), t.end());
    const auto t0 = Clock::now();
    Eigen::UmfPackLU<ColMatrix> lu(m);
    if (lu.info() != Eigen::Success) throw std::runtime_error("UMFPACK could not factorise");
    s.x = lu.solve(rhs);
    s.solve_s += seconds_since(t0);
    const Eigen::VectorXd residual = sys.K * s.x - sys.f;  // the nodal forces the obstacle makes
    std::vector<char> next(active.size(), 0);
    for (std::size_t i = 0; i < bd.contact.size(); ++i) {
      const NodalConstraint& con = bd.contact[i];
      const int vx = 2 * con.vertex;
      const Point r(residual[vx], residual[vx + 1]);
      const Point u(s.x[vx], s.x[vx + 1]);
      // The residual is the obstacle's force −λ_i d, plus a roller's along its prescribed axis.
      const double lambda_i = con.free_component < 0
                                  ? -r.dot(con.d)
                                  : -r[con.free_component] / con.d[con.free_component];
      s.contact_force[i] = active[i] ? lambda_i : 0.0;
      const double c = sys.K.coeff(vx, vx);
      next[i] = s.contact_force[i] + c * (u.dot(con.d) - con.gap) > 0;
    }
    if (next == active) {
      s.converged = true;
      break;
    }
    active = next;
  }
  s.iterations = std::min(s.iterations, kMaxIterations);
  s.active_set = std::move(active);
  return s;
}

/// The start of the active set iteration on a finer level: a coarse vertex as it was, a new
/// vertex active when both ends of the coarse edge it halves were.
std::vector<char> prolongated_active_set(const BoundaryData& coarse,
                                         const std::vector<char>& active, const BoundaryData& fine,
                                         const Mesh& coarse_mesh, const RefinementMaps& maps) {
  std::vector<char> vertex_active(coarse_mesh.num_vertices(), 0);
  for (std::size_t i = 0; i < coarse.contact.size(); ++i)
    vertex_active[coarse.contact[i].vertex] = active[i];
  std::vector<char> out(fine.contact.size(), 0);
  for (std::size_t i = 0; i < fine.contact.size(); ++i) {
    const int v = fine.contact[i].vertex;
    if (v < maps.num_coarse_vertices) {
      out[i] = vertex_active[v];
    } else {
      const auto& e = coarse_mesh.edge(maps.midpoint_edge[v - maps.num_coarse_vertices]);
      out[i] = vertex_active[e[0]] && vertex_active[e[1]];
    }
  }
  return out;
}

/// A body of revolution about the y axis: the mesh in x ≥ 0, and the axis (where x = 0 on the
/// boundary) held by a roller, u_x = 0 — the case must say so.
void check_axisymmetric(const Mesh& mesh, const BoundaryData& bd) {
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const double r = mesh.vertex(v).x();
    if (r < -1e-12) throw std::runtime_error("axisymmetric: the mesh must lie in x >= 0");
    if (std::abs(r) <= 1e-12 && std::isnan(bd.prescribed[2 * v]))
      throw std::runtime_error("axisymmetric: a vertex on the axis x = 0 needs u_x = 0");
  }
}

int run(const std::string& path, const Options& options) {
  const bool mixed = options.mixed;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  const CaseReadResult read = read_case(nlohmann::json::parse(in));
  if (!read.spec)
    throw std::runtime_error("invalid case: " + read.errors.front().pointer + ": " +
                             read.errors.front().detail);
  const CaseSpec& spec = *read.spec;
  if (mixed && spec.mesh.refinements < 1)
    throw std::runtime_error("mixed: the pressure mesh needs mesh.refinements ≥ 1");
  if (!mixed && spec.material.incompressible())
    throw std::runtime_error("p1 locks at λ = ∞: use --element mixed");
  const auto t0 = Clock::now();
  MeshHierarchy meshes = build_mesh_hierarchy(build_coarse_mesh(spec.mesh), spec.mesh.refinements);
  const double mesh_s = seconds_since(t0);
  // Nested: each level starts its active set iteration from the coarser level's active set, so
  // the finest level needs one or two factorisations instead of about eight.
  const int finest = meshes.num_levels() - 1;
  BoundaryData bd;
  Solution s;
  Assembled sys;
  double assembly_s = 0.0, solve_s = 0.0;
  int coarse_iterations = 0;
  for (int level = mixed ? 1 : 0; level <= finest; ++level) {
    const auto t1 = Clock::now();
    sys = assemble(meshes, level, spec, options);
    BoundaryData next = boundary_data(meshes.meshes[level], spec, options.axisymmetric, sys.f);
    if (options.axisymmetric) check_axisymmetric(meshes.meshes[level], next);
    assembly_s += seconds_since(t1);
    std::vector<char> start(next.contact.size(), 0);
    if (!s.active_set.empty())
      start = prolongated_active_set(bd, s.active_set, next, meshes.meshes[level - 1],
                                     meshes.maps[level]);
    bd = std::move(next);
    coarse_iterations += s.iterations;
    s = solve_contact(sys, bd, std::move(start));
    solve_s += s.solve_s;
  }
  Point force = Point::Zero();
  for (std::size_t i = 0; i < bd.contact.size(); ++i) force -= s.contact_force[i] * bd.contact[i].d;
  // A body of revolution's radial tractions cancel around the axis: its force is along it.
  if (options.axisymmetric) force.x() = 0.0;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const nlohmann::json out = {{"element", mixed ? "mixed" : "p1"},
                              {"axisymmetric", options.axisymmetric},
                              {"refinements", spec.mesh.refinements},
                              {"vertices", meshes.finest().num_vertices()},
                              {"dofs", sys.f.size()},
                              {"contact_vertices", bd.contact.size()},
                              {"active", std::count(s.active_set.begin(), s.active_set.end(), 1)},
                              {"iterations", s.iterations},
                              {"coarse_iterations", coarse_iterations},
                              {"converged", s.converged},
                              {"force", {force.x(), force.y()}},
                              {"mesh_s", mesh_s},
                              {"assembly_s", assembly_s},
                              {"solve_s", solve_s},
                              {"finest_solve_s", s.solve_s},
                              {"total_s", seconds_since(t0)},
                              {"peak_mib", usage.ru_maxrss / 1024.0}};
  std::cout << out.dump() << "\n";
  return s.converged ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
  std::string path, element = "p1";
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--element" && i + 1 < argc) {
      element = argv[++i];
    } else if (arg == "--axisymmetric") {
      options.axisymmetric = true;
    } else if (path.empty() && arg.rfind("--", 0) != 0) {
      path = arg;
    } else {
      path.clear();
      break;
    }
  }
  if (path.empty() || (element != "p1" && element != "mixed")) {
    std::fprintf(stderr, "usage: %s CASE.json [--element p1|mixed] [--axisymmetric]\n", argv[0]);
    return 2;
  }
  options.mixed = element == "mixed";
  try {
    return run(path, options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
