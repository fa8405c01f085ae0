#include "assembly/p2_rt1_assembler.hpp"

#include <omp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "assembly/assembly_pattern.hpp"
#include "fem/p2_rt1_element.hpp"

namespace fosls {

constexpr int kLocal = P2Rt1Space::kCellDofs;
using VecL = Eigen::Matrix<double, kLocal, 1>;
using RowL = Eigen::Matrix<double, 1, kLocal>;

namespace {

/// The functional's operators at one point of a triangle on its 28 DOFs (u: 2n + c, σ:
/// 12 + 2m + i), Cartesian, μ = 1.
struct PointOperators {
  Eigen::Matrix<double, 4, kLocal> constitutive;  ///< rows (ij) of Aσ − ε(u)
  RowL asymmetry;                                 ///< σ_01 − σ_10
  Eigen::Matrix<double, 2, kLocal> divergence;    ///< div σ_i
};

PointOperators point_operators(const P2Rt1Element& el, const Point& x, double kappa) {
  PointOperators op;
  op.constitutive.setZero();
  op.asymmetry.setZero();
  op.divergence.setZero();
  const auto grads = el.p2_gradients(x);
  const auto psi = el.rt1(x);
  const auto div = el.rt1_divergences(x);
  for (int n = 0; n < 6; ++n)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        op.constitutive(2 * i + j, 2 * n + i) -= 0.5 * grads[n][j];
        op.constitutive(2 * i + j, 2 * n + j) -= 0.5 * grads[n][i];
      }
  for (int m = 0; m < 8; ++m) {
    const int col = 12 + 2 * m;
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) op.constitutive(2 * i + j, col + i) += 0.5 * psi[m][j];
      for (int r = 0; r < 2; ++r) op.constitutive(3 * i, col + r) -= 0.5 * kappa * psi[m][r];
      op.divergence(i, col + i) = div[m];
    }
    op.asymmetry(col) += psi[m][1];
    op.asymmetry(col + 1) -= psi[m][0];
  }
  return op;
}

RowL volumetric_row(const PointOperators& op) {
  return op.constitutive.row(0) + op.constitutive.row(3);
}

Eigen::Vector2d scaled_body_force(const ProblemData<2>& data, const Point& x, double mu) {
  Eigen::Vector2d f;
  for (int i = 0; i < 2; ++i) f[i] = data.body_force[i] ? data.body_force[i](x.x(), x.y()) / mu : 0;
  return f;
}

Eigen::Matrix2d rotation_block(const Point& n) {
  Eigen::Matrix2d q;
  q << n.x(), -n.y(), n.y(), n.x();  // columns n, t
  return q;
}

}  // namespace

P2Rt1Assembler::P2Rt1Assembler(const P2Rt1Space& space, const ProblemData<2>& data)
    : space_(space), data_(data) {
  const Mesh& mesh = space.mesh();
  mu_ = data.material.mu;
  if (!(mu_ > 0)) throw std::invalid_argument("mu must be positive");
  const double lambda = data.material.lambda / mu_;
  kappa_ = data.material.incompressible() ? 0.5 : lambda / (2.0 * lambda + 2.0);
  node_gap_.assign(space.num_u_nodes(), std::numeric_limits<double>::infinity());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const int g = mesh.edge_group(e);
    if (g < 0 || data.groups[g].role != GroupRole::kContact) continue;
    const ContactData<2>& contact = data.groups[g].contact;
    if (contact.direction != ConstraintDirection::kBodyNormal || contact.friction.frictional())
      throw std::logic_error("order 2: frictionless contact along the body normal only");
    for (int a : {mesh.edge(e)[0], mesh.edge(e)[1], space.midpoint_node(e)}) {
      const Point n = space.is_contact_node(a) ? space.node_normal(a) : mesh.edge_normal(e);
      const double gap = locate_obstacle<2>(contact, space.node_position(a), n).gap;
      node_gap_[a] = std::min(node_gap_[a], capped_gap(gap, mesh.diameter()));
    }
  }
}

void P2Rt1Assembler::element_kernel(int t, Local& out) const {
  const FunctionalWeights& w = data_.weights;
  const P2Rt1Element el(space_.mesh(), t);
  out.K.setZero();
  out.b.setZero();
  out.c = 0.0;
  for (const TrianglePoint& p : kTriangleDegree5) {
    const Point x = el.point(p.l0, p.l1);
    const double wq = p.weight * el.area();
    const PointOperators op = point_operators(el, x, kappa_);
    out.K.noalias() += (2.0 * w.c2 * wq) * op.constitutive.transpose() * op.constitutive;
    if (w.c2_volumetric != 1.0) {
      const RowL trace = volumetric_row(op);
      out.K.noalias() += (w.c2 * wq * (w.c2_volumetric - 1.0)) * trace.transpose() * trace;
    }
    if (w.c4 != 0.0) out.K.noalias() += (2.0 * w.c4 * wq) * op.asymmetry.transpose() * op.asymmetry;
    out.K.noalias() += (2.0 * w.c1 * wq) * op.divergence.transpose() * op.divergence;
    const Eigen::Vector2d f = scaled_body_force(data_, x, mu_);
    out.b.noalias() -= (2.0 * w.c1 * wq) * op.divergence.transpose() * f;
    out.c += w.c1 * wq * f.squaredNorm();
  }
}

void P2Rt1Assembler::rotate_local(int t, Local& loc) const {
  const Mesh& mesh = space_.mesh();
  auto rotate = [&loc](int o, const Point& n) {
    const Eigen::Matrix2d q = rotation_block(n);
    loc.K.middleCols<2>(o) = (loc.K.middleCols<2>(o) * q).eval();
    loc.K.middleRows<2>(o) = (q.transpose() * loc.K.middleRows<2>(o)).eval();
    loc.b.segment<2>(o) = (q.transpose() * loc.b.segment<2>(o)).eval();
  };
  for (int k = 0; k < 3; ++k) {
    const int e = mesh.triangle_edge(t, k);
    const int nodes[2] = {mesh.triangle(t)[k], space_.midpoint_node(e)};
    for (int s = 0; s < 2; ++s)
      if (space_.is_contact_node(nodes[s])) rotate(2 * (3 * s + k), space_.node_normal(nodes[s]));
    if (space_.is_contact_edge(e))
      for (int j = 0; j < 2; ++j) rotate(12 + 2 * (2 * k + j), mesh.edge_normal(e));
  }
}

AssembledProblem P2Rt1Assembler::assemble_system(const Deadline& deadline) const {
  const int n_free = space_.num_free();
  AssembledProblem out;
  out.stress_scale = mu_;
  out.vertex_gap = node_gap_;
  const Vector xd = essential_values();
  AssemblyPattern pattern = assembly_pattern(space_, omp_get_max_threads(), deadline);
  Vector b = Vector::Zero(n_free);
  out.qp.constant = scatter_local_systems<P2Rt1Space>(
      space_, pattern, xd, b,
      [this](int t, Local& loc) {
        element_kernel(t, loc);
        rotate_local(t, loc);
      },
      ConstantSum::kCellOrder, deadline);
  add_contact_terms(xd, pattern.matrix, b);
  out.qp.A.swap(pattern.matrix);
  out.qp.b = std::move(b);
  out.qp.lower = Vector::Constant(n_free, -kNoBound);
  out.qp.upper = Vector::Constant(n_free, kNoBound);
  for (int f = 0; f < n_free; ++f) {
    const int d = space_.free_to_full()[f];
    if (space_.role(d) == DofRole::kNormalU) out.qp.upper[f] = node_gap_[d / 2];
    if (space_.role(d) == DofRole::kNormalS) out.qp.upper[f] = 0.0;
  }
  out.fixed_values = xd;
  return out;
}

Vector P2Rt1Assembler::essential_values() const {
  const Mesh& mesh = space_.mesh();
  Vector xd = Vector::Zero(space_.num_dofs());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const int g = mesh.edge_group(e);
    if (g < 0) continue;
    const GroupData<2>& gd = data_.groups[g];
    if (const int prescribed = gd.role == GroupRole::kDirichlet ? gd.prescribed & 3 : 0) {
      for (int a : {mesh.edge(e)[0], mesh.edge(e)[1], space_.midpoint_node(e)}) {
        const Point x = space_.node_position(a);
        for (int c = 0; c < 2; ++c) {
          if (!(prescribed & (1 << c))) continue;
          const double value = gd.values[c] ? gd.values[c](x.x(), x.y()) : 0.0;
          if (space_.is_contact_node(a)) {
            const Point& n = space_.node_normal(a);  // a roller along the tangent
            xd[space_.u_dof(a, 1)] = (c == 0 ? -n.y() : n.x()) * value;
          } else {
            xd[space_.u_dof(a, c)] = value;
          }
        }
      }
    } else if (gd.role == GroupRole::kNeumann) {
      set_neumann_values(e, gd, xd);
    }
  }
  for (int d = 0; d < space_.num_dofs(); ++d)
    if (space_.role(d) != DofRole::kFixed) xd[d] = 0.0;
  return xd;
}

void P2Rt1Assembler::set_neumann_values(int e, const GroupData<2>& gd, Vector& xd) const {
  const Mesh& mesh = space_.mesh();
  const Point p = mesh.vertex(mesh.edge(e)[0]), q = mesh.vertex(mesh.edge(e)[1]);
  const double len = (q - p).norm();
  const Point n = mesh.edge_normal(e);
  for (int c = 0; c < 2; ++c) {
    const ScalarFunction& t = gd.normal_pressure ? gd.values[0] : gd.values[c];
    const double factor = gd.normal_pressure ? -n[c] : 1.0;
    double moment[2] = {0.0, 0.0};  // ∫ t λ_p ds / |e|, ∫ t λ_q ds / |e|
    if (t)
      for (int g = 0; g < 3; ++g) {
        const Point x = p + kEdgeGaussX[g] * (q - p);
        const double value = factor * t(x.x(), x.y());
        moment[0] += kEdgeGaussW[g] * value * (1.0 - kEdgeGaussX[g]);
        moment[1] += kEdgeGaussW[g] * value * kEdgeGaussX[g];
      }
    // The P1 projection's end values (the P1 mass matrix on [0, 1] is [1/3 1/6; 1/6 1/3]).
    const double end_value[2] = {4.0 * moment[0] - 2.0 * moment[1],
                                 4.0 * moment[1] - 2.0 * moment[0]};
    for (int j = 0; j < 2; ++j) xd[space_.sigma_edge_dof(e, j, c)] = 0.5 * len * end_value[j] / mu_;
  }
}

double P2Rt1Assembler::contact_weight(int a, int j) {
  // ∫_0^1 N_a(s) λ_j(s) ds ·2: σ_nn = (2/|e|) Σ_j S_j λ_j and ds = |e| ds_ref.
  double w = 0.0;
  for (int g = 0; g < 3; ++g) {
    const double s = kEdgeGaussX[g];
    const double n = a == 0 ? (1 - s) * (1 - 2 * s) : a == 1 ? s * (2 * s - 1) : 4 * s * (1 - s);
    w += kEdgeGaussW[g] * n * (j == 0 ? 1 - s : s);
  }
  return 2.0 * w;
}

std::array<std::pair<int, double>, 2> P2Rt1Assembler::normal_displacement(int a, int e) const {
  if (space_.is_contact_node(a)) return {{{space_.u_dof(a, 0), 1.0}, {space_.u_dof(a, 1), 0.0}}};
  const Point n = space_.mesh().edge_normal(e);
  return {{{space_.u_dof(a, 0), n.x()}, {space_.u_dof(a, 1), n.y()}}};
}

void P2Rt1Assembler::add_contact_terms(const Vector& xd, SparseMatrix& a, Vector& b) const {
  const Mesh& mesh = space_.mesh();
  const double c3 = data_.weights.c3;
  if (c3 == 0.0) return;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!space_.is_contact_edge(e)) continue;
    const std::array<int, 3> nodes = {mesh.edge(e)[0], mesh.edge(e)[1], space_.midpoint_node(e)};
    for (int j = 0; j < 2; ++j) {
      const int s = space_.free_index(space_.sigma_edge_dof(e, j, 0));
      for (int k = 0; k < 3; ++k) {
        const double beta = c3 * contact_weight(k, j);
        b[s] += beta * node_gap_[nodes[k]];
        for (auto [dof, factor] : normal_displacement(nodes[k], e)) {
          if (factor == 0.0) continue;
          const int fu = space_.free_index(dof);
          if (fu >= 0) {
            a.valuePtr()[entry_position(a, s, fu)] += beta * factor;
            a.valuePtr()[entry_position(a, fu, s)] += beta * factor;
          } else {
            b[s] -= beta * factor * xd[dof];
          }
        }
      }
    }
  }
}

Vector P2Rt1Assembler::full_vector(const AssembledProblem& p, const Vector& x_free) const {
  return full_from_free(p.fixed_values, space_.free_to_full(), x_free);
}

FunctionalParts P2Rt1Assembler::functional(const Vector& x_full) const {
  const Mesh& mesh = space_.mesh();
  const FunctionalWeights& w = data_.weights;
  const Vector x = space_.rotation() * x_full;
  FunctionalParts parts;
  parts.element.assign(mesh.num_triangles(), 0.0);
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const P2Rt1Element el(mesh, t);
    const auto dofs = space_.cell_dofs(t);
    VecL xl;
    for (int i = 0; i < kLocal; ++i) xl[i] = x[dofs[i]];
    double m = 0, c = 0, as = 0;
    for (const TrianglePoint& p : kTriangleDegree5) {
      const Point at = el.point(p.l0, p.l1);
      const double wq = p.weight * el.area();
      const PointOperators op = point_operators(el, at, kappa_);
      m += w.c1 * wq * (op.divergence * xl + scaled_body_force(data_, at, mu_)).squaredNorm();
      c += w.c2 * wq * (op.constitutive * xl).squaredNorm();
      if (w.c2_volumetric != 1.0)
        c += 0.5 * w.c2 * wq * (w.c2_volumetric - 1.0) * std::pow(volumetric_row(op).dot(xl), 2);
      as += w.c4 * wq * std::pow(op.asymmetry.dot(xl), 2);
    }
    parts.element[t] = m + c + as;
    parts.momentum += m, parts.constitutive += c, parts.asymmetry += as;
  }
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!space_.is_contact_edge(e)) continue;
    const std::array<int, 3> nodes = {mesh.edge(e)[0], mesh.edge(e)[1], space_.midpoint_node(e)};
    double term = 0.0;
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 3; ++k) {
        double un = -node_gap_[nodes[k]];
        for (auto [dof, factor] : normal_displacement(nodes[k], e)) un += factor * x_full[dof];
        term += w.c3 * contact_weight(k, j) * x_full[space_.sigma_edge_dof(e, j, 0)] * un;
      }
    parts.contact += term;
    parts.element[mesh.edge_triangles(e)[0]] += term;
  }
  return parts;
}

Point P2Rt1Assembler::contact_force(const Vector& x_full) const {
  const Mesh& mesh = space_.mesh();
  Point force = Point::Zero();
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!space_.is_contact_edge(e)) continue;
    const Eigen::Matrix2d q = rotation_block(mesh.edge_normal(e));
    for (int j = 0; j < 2; ++j) {
      const int d = space_.sigma_edge_dof(e, j, 0);
      force += q * Point(x_full[d], x_full[d + 1]);  // the rows' fluxes through the edge
    }
  }
  return mu_ * force;
}

}  // namespace fosls
