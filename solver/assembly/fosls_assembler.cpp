#include "assembly/fosls_assembler.hpp"

#include <omp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "assembly/assembly_pattern.hpp"
#include "fem/simplex_element.hpp"

namespace fosls {

using Mat12 = Eigen::Matrix<double, 12, 12>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Row12 = Eigen::Matrix<double, 1, 12>;

struct FoslsAssembler::Local {
  Mat12 K;
  Vec12 b;
  double c = 0.0;
};

namespace {

/// Operators of one triangle at one quadrature point, acting on the 12 local DOFs
/// (u: 2k + c, σ: 6 + 2k + i), all in Cartesian coordinates with μ = 1 (scaled stresses).
struct PointOperators {
  Eigen::Matrix<double, 4, 12> constitutive;  ///< rows (ij) = 00, 01, 10, 11 of Aσ − ε(u)
  Row12 asymmetry;                            ///< σ_01 − σ_10
};

PointOperators point_operators(const SimplexElement<2>& g, const Point& x, double kappa) {
  PointOperators op;
  op.constitutive.setZero();
  op.asymmetry.setZero();
  const double inv2mu = 0.5;
  for (int k = 0; k < 3; ++k) {
    const Point psi = g.rt0(k, x);
    const Point grad = g.grad_p1(k);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        // Aσ: (σ_ij − κ δ_ij tr σ) / (2μ), σ_ij = Σ_k S_{i,k} ψ_k,j.
        op.constitutive(2 * i + j, 6 + 2 * k + i) += inv2mu * psi[j];
        if (i == j)
          for (int m = 0; m < 2; ++m)
            op.constitutive(2 * i + i, 6 + 2 * k + m) -= inv2mu * kappa * psi[m];
        // −ε_ij = −½(∂_j u_i + ∂_i u_j).
        op.constitutive(2 * i + j, 2 * k + i) -= 0.5 * grad[j];
        op.constitutive(2 * i + j, 2 * k + j) -= 0.5 * grad[i];
      }
    }
    op.asymmetry(6 + 2 * k + 0) += psi[1];
    op.asymmetry(6 + 2 * k + 1) -= psi[0];
  }
  return op;
}

/// tr(Aσ − ε(u)) at a point: the volumetric part of the constitutive residual, whose square
/// the c2 term weights by ½ (the Frobenius norm) and `c2_volumetric` re-weights.
Row12 volumetric_row(const PointOperators& op) {
  return op.constitutive.row(0) + op.constitutive.row(3);
}

/// div σ_i as a function of the local DOFs (constant on the triangle).
Eigen::Matrix<double, 2, 12> divergence_operator(const SimplexElement<2>& g) {
  Eigen::Matrix<double, 2, 12> d;
  d.setZero();
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 2; ++i) d(i, 6 + 2 * k + i) = g.rt0_div(k);
  return d;
}

/// Gauss–Legendre points on [0, 1] (3 points, exact for degree 5).
constexpr std::array<double, 3> kGaussX = {0.1127016653792583, 0.5, 0.8872983346207417};
constexpr std::array<double, 3> kGaussW = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

}  // namespace

std::vector<Point> obstacle_vertex_normals(const Mesh& mesh, const ProblemData& data) {
  bool any = false;
  for (const auto& g : data.groups)
    any |= g.role == GroupRole::kContact &&
           g.contact.direction == ConstraintDirection::kObstacleNormal;
  if (!any) return {};
  std::vector<Point> averaged(mesh.num_vertices(), Point::Zero());
  std::vector<int> group(mesh.num_vertices(), -1);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    int g = mesh.edge_group(e);
    if (g < 0 || data.groups[g].role != GroupRole::kContact) continue;
    for (int v : mesh.edge(e)) {
      averaged[v] += mesh.edge_normal(e);
      group[v] = g;
    }
  }
  std::vector<Point> normals(mesh.num_vertices(), Point::Zero());
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (group[v] < 0) continue;
    Point n = averaged[v].normalized();
    normals[v] = locate_obstacle(data.groups[group[v]].contact, mesh.vertex(v), n).direction;
  }
  return normals;
}

FoslsAssembler::FoslsAssembler(const FoslsSpace<2>& space, const ProblemData& data)
    : space_(space), data_(data) {
  const Mesh& mesh = space.mesh();
  mu_ = data.material.mu;
  if (!(mu_ > 0)) throw std::invalid_argument("mu must be positive");
  const double lambda = data.material.lambda / mu_;  // scaled: μ = 1
  kappa_ = data.material.incompressible() ? 0.5 : lambda / (2.0 * lambda + 2.0);
  // Without a body force (most contact cases) nothing is stored: six zeros per triangle were a
  // measurable part of a large solve (docs/performance.md, "Measurements behind choices in the
  // code").
  if (data.body_force[0] || data.body_force[1]) body_force_.resize(mesh.num_triangles());
  for (int t = 0; t < static_cast<int>(body_force_.size()); ++t) {
    const SimplexElement<2> g(mesh, t);
    const auto points = g.quadrature_points();
    for (int q = 0; q < 3; ++q) {
      Point x = points[q];
      for (int i = 0; i < 2; ++i)
        body_force_[t][2 * q + i] =
            data.body_force[i] ? data.body_force[i](x.x(), x.y()) / mu_ : 0.0;
    }
  }
  // Gaps at the vertices of contact edges, capped at a length far beyond the body so that
  // a ray that misses the obstacle leaves the point effectively unconstrained.
  double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
  for (const auto& p : mesh.vertices()) {
    lo_x = std::min(lo_x, p.x()), hi_x = std::max(hi_x, p.x());
    lo_y = std::min(lo_y, p.y()), hi_y = std::max(hi_y, p.y());
  }
  const double far = 10.0 * std::hypot(hi_x - lo_x, hi_y - lo_y);
  vertex_gap_.assign(mesh.num_vertices(), std::numeric_limits<double>::infinity());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    int g = mesh.edge_group(e);
    if (g < 0 || data.groups[g].role != GroupRole::kContact) continue;
    for (int v : mesh.edge(e)) {
      Point n = space.is_contact_vertex(v) ? space.vertex_normal(v) : mesh.edge_normal(e);
      ContactData body = data.groups[g].contact;
      body.direction = ConstraintDirection::kBodyNormal;  // n already is the constraint direction
      double gap = locate_obstacle(body, mesh.vertex(v), n).gap;
      if (data.groups[g].contact.direction == ConstraintDirection::kObstacleNormal &&
          body.obstacle.kind != RigidObstacle::Kind::kGap)
        gap = locate_obstacle(data.groups[g].contact, mesh.vertex(v), n).gap;
      if (!std::isfinite(gap) || gap > far) gap = far;
      vertex_gap_[v] = std::min(vertex_gap_[v], gap);
    }
  }
}

void FoslsAssembler::element_kernel(int t, Local& out) const {
  const FunctionalWeights& w = data_.weights;
  const SimplexElement<2> g(space_.mesh(), t);
  const auto points = g.quadrature_points();
  const double wq = g.measure / 3.0;  // edge-midpoint rule, exact for degree 2
  const auto div = divergence_operator(g);
  out.K.setZero();
  out.b.setZero();
  out.c = 0.0;
  for (int q = 0; q < 3; ++q) {
    const PointOperators op = point_operators(g, points[q], kappa_);
    out.K.noalias() += (2.0 * w.c2 * wq) * op.constitutive.transpose() * op.constitutive;
    if (w.c2_volumetric != 1.0) {
      const auto trace = volumetric_row(op);
      out.K.noalias() += (w.c2 * wq * (w.c2_volumetric - 1.0)) * trace.transpose() * trace;
    }
    if (w.c4 != 0.0) out.K.noalias() += (2.0 * w.c4 * wq) * op.asymmetry.transpose() * op.asymmetry;
    const Eigen::Vector2d f = body_force(t, q);
    out.b.noalias() -= (2.0 * w.c1 * wq) * div.transpose() * f;
    out.c += w.c1 * wq * f.squaredNorm();
  }
  out.K.noalias() += (2.0 * w.c1 * g.measure) * div.transpose() * div;
}

void FoslsAssembler::rotate_local(int t, Local& loc) const {
  const Mesh& mesh = space_.mesh();
  for (int k = 0; k < 3; ++k) {
    for (int kind = 0; kind < 2; ++kind) {
      Point n;
      if (kind == 0) {
        int v = mesh.triangle(t)[k];
        if (!space_.is_contact_vertex(v)) continue;
        n = space_.vertex_normal(v);
      } else {
        int e = mesh.triangle_edge(t, k);
        if (!space_.is_contact_edge(e)) continue;
        n = mesh.edge_normal(e);
      }
      const int o = kind == 0 ? 2 * k : 6 + 2 * k;
      Eigen::Matrix2d q;
      q << n.x(), -n.y(), n.y(), n.x();  // columns n, t
      loc.K.middleCols<2>(o) = (loc.K.middleCols<2>(o) * q).eval();
      loc.K.middleRows<2>(o) = (q.transpose() * loc.K.middleRows<2>(o)).eval();
      loc.b.segment<2>(o) = (q.transpose() * loc.b.segment<2>(o)).eval();
    }
  }
}

AssembledProblem FoslsAssembler::assemble_system(const Deadline& deadline) const {
  const int n_free = space_.num_free();
  AssembledProblem out;
  out.stress_scale = mu_;
  out.vertex_gap = vertex_gap_;
  Vector xd = essential_values();
  // Pattern first, values in place (assembly_pattern.hpp): each thread writes only
  // the columns it owns, visiting their triangles in increasing order (AssemblyPartition).
  const int threads = omp_get_max_threads();
  AssemblyPattern pattern = assembly_pattern(space_, threads, deadline);
  Vector b = Vector::Zero(n_free);
  const std::vector<double> constants = add_element_terms(xd, pattern, threads, b, deadline);
  add_contact_terms(xd, pattern.matrix, b);
  out.qp.A.swap(pattern.matrix);  // Eigen 3.4's SparseMatrix has no move: std::move would copy
  out.qp.b = std::move(b);
  out.qp.constant = 0.0;
  for (double c : constants) out.qp.constant += c;
  out.qp.lower = Vector::Constant(n_free, -kNoBound);
  out.qp.upper = Vector::Constant(n_free, kNoBound);
  set_contact_bounds(out.qp.upper);
  out.friction = friction_layout(space_, data_, xd, out.kinks);
  if (!out.friction.empty()) {
    set_friction_bounds(out.friction, Vector::Zero(n_free), out.qp, out.kinks);
    for (const FrictionEdge& f : out.friction.edges) out.qp.row_obstacles.push_back(f.st);
    out.qp.row_obstacles.insert(out.qp.row_obstacles.end(), out.kinks.dof.begin(),
                                out.kinks.dof.end());
  }
  out.fixed_values = std::move(xd);
  return out;
}

Vector FoslsAssembler::essential_values() const {
  const Mesh& mesh = space_.mesh();
  const int n_full = space_.num_dofs();
  Vector xd = Vector::Zero(n_full);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    int g = mesh.edge_group(e);
    if (g < 0) continue;
    const GroupData& gd = data_.groups[g];
    const auto& pq = mesh.edge(e);
    if (const int prescribed = gd.role == GroupRole::kDirichlet ? gd.prescribed & 3 : 0) {
      for (int v : pq)
        for (int c = 0; c < 2; ++c) {
          if (!(prescribed & (1 << c))) continue;
          const double value =
              gd.values[c] ? gd.values[c](mesh.vertex(v).x(), mesh.vertex(v).y()) : 0.0;
          if (space_.is_contact_vertex(v)) {
            // A roller through the contact zone: its axis is the tangent t = (−n_y, n_x), so
            // the fixed rotated DOF U_t = t·U = t_c u_c (fosls_space.cpp).
            const Point& n = space_.vertex_normal(v);
            xd[space_.u_dof(v, 1)] = (c == 0 ? -n.y() : n.x()) * value;
          } else {
            xd[space_.u_dof(v, c)] = value;
          }
        }
    } else if (gd.role == GroupRole::kNeumann) {
      const Point a = mesh.vertex(pq[0]), b = mesh.vertex(pq[1]);
      const double len = (b - a).norm();
      // A normal pressure p is the traction t = −p n with the edge's outward normal n.
      const Point n = mesh.edge_normal(e);
      for (int c = 0; c < 2; ++c) {
        const ScalarFunction& t = gd.normal_pressure ? gd.values[0] : gd.values[c];
        const double factor = gd.normal_pressure ? -n[c] : 1.0;
        double flux = 0.0;
        if (t)
          for (int q = 0; q < 3; ++q) {
            Point x = a + kGaussX[q] * (b - a);
            flux += kGaussW[q] * t(x.x(), x.y());
          }
        xd[space_.sigma_dof(e, c)] = factor * flux * len / mu_;
      }
    }
  }
  // Dirichlet vertices at the end of a Neumann edge keep their displacement; fixed σ of
  // Neumann edges keep the flux. Clear values of DOFs that are not fixed.
  for (int d = 0; d < n_full; ++d)
    if (space_.role(d) != DofRole::kFixed) xd[d] = 0.0;

  return xd;
}

std::vector<double> FoslsAssembler::add_element_terms(const Vector& xd, AssemblyPattern& pattern,
                                                      int threads, Vector& b,
                                                      const Deadline& deadline) const {
  SparseMatrix& a = pattern.matrix;
  const AssemblyPartition& part = pattern.partition;
  double* values = a.valuePtr();
  std::vector<double> cs(threads, 0.0);
  // An exception cannot leave the parallel region: a thread that sees the deadline passed
  // stops every thread's loop, and the throw comes after the region.
  std::atomic<bool> out_of_time{false};
#pragma omp parallel num_threads(threads)
  // Each part once, also when the runtime gives fewer threads than asked for.
  for (int tid = omp_get_thread_num(); tid < threads; tid += omp_get_num_threads()) {
    double& c = cs[tid];
    Local loc;
    int polled = 0;
    for (int t : part.triangles[tid]) {
      if (deadline.is_set() && ++polled % Deadline::kPollEvery == 0 &&
          (out_of_time.load(std::memory_order_relaxed) || deadline.passed())) {
        out_of_time.store(true, std::memory_order_relaxed);
        break;
      }
      element_kernel(t, loc);
      rotate_local(t, loc);
      const auto dofs = triangle_dofs(space_, t);
      std::array<int, 12> free;
      for (int i = 0; i < 12; ++i) free[i] = space_.free_index(dofs[i]);
      const bool in_range = t >= part.range_begin[tid] && t < part.range_begin[tid + 1];
      if (in_range) c += loc.c;
      for (int i = 0; i < 12; ++i) {
        const int fi = free[i];
        if (fi >= 0) {
          if (part.owner[fi] != tid) continue;
          double bi = loc.b[i];
          for (int j = 0; j < 12; ++j)
            if (free[j] < 0) bi -= loc.K(i, j) * xd[dofs[j]];
          b[fi] += bi;
        } else if (in_range) {
          const double xi = xd[dofs[i]];
          c -= loc.b[i] * xi;
          for (int j = 0; j < 12; ++j)
            if (free[j] < 0) c += 0.5 * loc.K(i, j) * xi * xd[dofs[j]];
        }
      }
      for (int j = 0; j < 12; ++j) {
        const int fj = free[j];
        if (fj < 0 || part.owner[fj] != tid) continue;
        for (int i = 0; i < 12; ++i)
          if (free[i] >= 0) values[entry_position(a, free[i], fj)] += loc.K(i, j);
      }
    }
  }
  if (out_of_time) throw TimeLimitReached("assembling the finest level");
  return cs;
}

void FoslsAssembler::add_contact_terms(const Vector& xd, SparseMatrix& a, Vector& b) const {
  const Mesh& mesh = space_.mesh();
  double* values = a.valuePtr();
  // Contact term C3 ⟨u·n − g, σ_nn⟩ on each contact edge: σ_nn = S_n/|e| is constant, u·n and
  // g are linear along the edge, so the term is C3 S_n ((u·n)_p + (u·n)_q − g_p − g_q) / 2.
  // On a frictional edge C3 ⟨u·t − o, σ_nt⟩ likewise, o the reference state's u·t.
  // Its entries couple DOFs of the edge's triangle, so they are in the pattern.
  const double c3 = data_.weights.c3;
  // C3 S (d·u_v)/2 for the flux DOF s: U_n or U_t (`component`) at a contact vertex, else d·u.
  auto couple = [&](int s, int v, int component, const Point& d) {
    std::array<std::pair<int, double>, 2> terms;
    if (space_.is_contact_vertex(v))
      terms = {{{space_.u_dof(v, component), 0.5 * c3}, {space_.u_dof(v, 1 - component), 0.0}}};
    else
      terms = {{{space_.u_dof(v, 0), 0.5 * c3 * d.x()}, {space_.u_dof(v, 1), 0.5 * c3 * d.y()}}};
    for (auto [dof, val] : terms) {
      if (val == 0.0) continue;
      const int fj = space_.free_index(dof);
      if (fj >= 0) {
        values[entry_position(a, s, fj)] += val;
        values[entry_position(a, fj, s)] += val;
      } else {
        b[s] -= val * xd[dof];
      }
    }
  };
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!space_.is_contact_edge(e) || c3 == 0.0) continue;
    const int sn = space_.free_index(space_.sigma_dof(e, 0));
    const int st = space_.role(space_.sigma_dof(e, 1)) == DofRole::kTangentialS
                       ? space_.free_index(space_.sigma_dof(e, 1))
                       : -1;
    const Point ne = mesh.edge_normal(e), te(-ne.y(), ne.x());
    double gbar = 0.0, obar = 0.0;
    for (int v : mesh.edge(e)) {
      gbar += 0.5 * vertex_gap_[v];
      couple(sn, v, 0, ne);
      if (st < 0) continue;
      const Point n = space_.is_contact_vertex(v) ? space_.vertex_normal(v) : ne;
      obar += 0.5 * reference_slip_origin(data_, v, Point(-n.y(), n.x()));
      couple(st, v, 1, te);
    }
    b[sn] += c3 * gbar;
    if (st >= 0) b[st] += c3 * obar;
  }
}

void FoslsAssembler::set_contact_bounds(Vector& upper) const {
  for (int f = 0; f < space_.num_free(); ++f) {
    const int d = space_.free_to_full()[f];
    if (space_.role(d) == DofRole::kNormalU) upper[f] = vertex_gap_[d / 2];
    if (space_.role(d) == DofRole::kNormalS) upper[f] = 0.0;
  }
}

Vector full_from_free(const Vector& fixed_values, const std::vector<int>& free_to_full,
                      const Vector& x_free) {
  Vector x = fixed_values;
  for (std::size_t f = 0; f < free_to_full.size(); ++f) x[free_to_full[f]] = x_free[f];
  return x;
}

Vector FoslsAssembler::full_vector(const AssembledProblem& p, const Vector& x_free) const {
  return full_from_free(p.fixed_values, space_.free_to_full(), x_free);
}

double FoslsAssembler::edge_mean_penetration(const Vector& x_full, int e) const {
  const Mesh& mesh = space_.mesh();
  const Point ne = mesh.edge_normal(e);
  double penetration = 0.0;
  for (int v : mesh.edge(e)) {
    const double un = space_.is_contact_vertex(v) ? x_full[space_.u_dof(v, 0)]
                                                  : ne.x() * x_full[space_.u_dof(v, 0)] +
                                                        ne.y() * x_full[space_.u_dof(v, 1)];
    penetration += 0.5 * (un - vertex_gap_[v]);
  }
  return penetration;
}

FunctionalParts FoslsAssembler::functional(const Vector& x_full) const {
  const Mesh& mesh = space_.mesh();
  const FunctionalWeights& w = data_.weights;
  const Vector x_cart = space_.rotation() * x_full;
  FunctionalParts parts;
  parts.element.assign(mesh.num_triangles(), 0.0);
  double mom = 0, con = 0, asym = 0;
#pragma omp parallel for reduction(+ : mom, con, asym) schedule(static)
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const SimplexElement<2> g(mesh, t);
    const auto points = g.quadrature_points();
    const auto dofs = triangle_dofs(space_, t);
    Vec12 xl;
    for (int i = 0; i < 12; ++i) xl[i] = x_cart[dofs[i]];
    const double wq = g.measure / 3.0;
    const Eigen::Vector2d div = divergence_operator(g) * xl;
    double m = 0, c = 0, a = 0;
    for (int q = 0; q < 3; ++q) {
      const PointOperators op = point_operators(g, points[q], kappa_);
      const Eigen::Vector2d f = body_force(t, q);
      m += w.c1 * wq * (div + f).squaredNorm();
      c += w.c2 * wq * (op.constitutive * xl).squaredNorm();
      if (w.c2_volumetric != 1.0)
        c += 0.5 * w.c2 * wq * (w.c2_volumetric - 1.0) * std::pow(volumetric_row(op).dot(xl), 2);
      a += w.c4 * wq * std::pow(op.asymmetry.dot(xl), 2);
    }
    parts.element[t] = m + c + a;
    mom += m, con += c, asym += a;
  }
  parts.momentum = mom, parts.constitutive = con, parts.asymmetry = asym;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!space_.is_contact_edge(e)) continue;
    const double term = w.c3 * x_full[space_.sigma_dof(e, 0)] * edge_mean_penetration(x_full, e);
    parts.contact += term;
    parts.element[mesh.edge_triangles(e)[0]] += term;
  }
  return parts;
}

}  // namespace fosls
