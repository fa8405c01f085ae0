#include "assembly/fosls_assembler.hpp"

#include <omp.h>

#include <cmath>
#include <stdexcept>

#include "assembly/assembly_pattern.hpp"
#include "assembly/element_operators.hpp"
#include "fem/contact_frame.hpp"
#include "fem/facet_quadrature.hpp"

namespace fosls {

template <int dim>
FoslsAssembler<dim>::FoslsAssembler(const FoslsSpace<dim>& space, const ProblemData<dim>& data)
    : space_(space), data_(data) {
  const SimplexMesh<dim>& mesh = space.mesh();
  mu_ = data.material.mu;
  if (!(mu_ > 0)) throw std::invalid_argument("mu must be positive");
  const double lambda = data.material.lambda / mu_;  // scaled: μ = 1
  kappa_ = data.material.incompressible() ? 1.0 / dim : lambda / (dim * lambda + 2.0);
  // Without a body force (most contact cases) nothing is stored: six zeros per triangle were a
  // measurable part of a large solve (docs/performance.md, "Measurements behind choices in the
  // code").
  bool any_force = false;
  for (const auto& f : data.body_force) any_force |= static_cast<bool>(f);
  if (any_force) body_force_.resize(mesh.num_cells());
  for (int t = 0; t < static_cast<int>(body_force_.size()); ++t) {
    const auto points = SimplexElement<dim>(mesh, t).quadrature_points();
    for (int q = 0; q <= dim; ++q)
      for (int i = 0; i < dim; ++i)
        body_force_[t][dim * q + i] =
            data.body_force[i] ? evaluate<dim>(data.body_force[i], points[q]) / mu_ : 0.0;
  }
  // Gaps at the vertices of contact facets, along each vertex's constraint direction (a
  // Dirichlet vertex has no frame: its facet's normal).
  const double diameter = mesh.diameter();
  vertex_gap_.assign(mesh.num_vertices(), std::numeric_limits<double>::infinity());
  for (int f = 0; f < mesh.num_facets(); ++f) {
    const int g = mesh.facet_group(f);
    if (g < 0 || data.groups[g].role != GroupRole::kContact) continue;
    const ContactData<dim>& contact = data.groups[g].contact;
    for (int v : mesh.facet(f)) {
      const Vec<dim> n =
          space.is_contact_vertex(v) ? space.vertex_normal(v) : Vec<dim>(mesh.facet_normal(f));
      // n already is the constraint direction; along the obstacle's normal a plane or ball
      // measures the gap itself.
      double gap =
          locate_obstacle<dim>(contact, mesh.vertex(v), n, ConstraintDirection::kBodyNormal).gap;
      if (contact.direction == ConstraintDirection::kObstacleNormal &&
          contact.obstacle.kind != RigidObstacle<dim>::Kind::kGap)
        gap = locate_obstacle<dim>(contact, mesh.vertex(v), n).gap;
      vertex_gap_[v] = std::min(vertex_gap_[v], capped_gap(gap, diameter));
    }
  }
}

template <int dim>
Vec<dim> FoslsAssembler<dim>::body_force(int t, int q) const {
  if (body_force_.empty()) return Vec<dim>::Zero();
  return Eigen::Map<const Vec<dim>>(body_force_[t].data() + dim * q);
}

template <int dim>
void FoslsAssembler<dim>::element_kernel(int t, Local& out) const {
  const FunctionalWeights& w = data_.weights;
  const SimplexElement<dim> e(space_.mesh(), t);
  const auto points = e.quadrature_points();
  const double wq = e.quadrature_weight();
  const auto div = divergence_operator<dim>(e);
  out.K.setZero();
  out.b.setZero();
  out.c = 0.0;
  for (int q = 0; q <= dim; ++q) {
    const PointOperators<dim> op = point_operators<dim>(e, points[q], kappa_);
    out.K.noalias() += (2.0 * w.c2 * wq) * op.constitutive.transpose() * op.constitutive;
    if (w.c2_volumetric != 1.0) {
      // |R|² = |dev R|² + (tr R)²/d: the volumetric part re-weighted (docs/method.md §2.2).
      const auto trace = volumetric_row<dim>(op);
      out.K.noalias() +=
          (2.0 * w.c2 * wq * (w.c2_volumetric - 1.0) / dim) * trace.transpose() * trace;
    }
    if (w.c4 != 0.0) out.K.noalias() += (2.0 * w.c4 * wq) * op.asymmetry.transpose() * op.asymmetry;
    const Vec<dim> f = body_force(t, q);
    out.b.noalias() -= (2.0 * w.c1 * wq) * div.transpose() * f;
    out.c += w.c1 * wq * f.squaredNorm();
  }
  out.K.noalias() += (2.0 * w.c1 * e.measure) * div.transpose() * div;
}

template <int dim>
void FoslsAssembler<dim>::rotate_local(int t, Local& loc) const {
  const SimplexMesh<dim>& mesh = space_.mesh();
  auto rotate = [&loc](int o, const Mat<dim>& q) {
    loc.K.template middleCols<dim>(o) = (loc.K.template middleCols<dim>(o) * q).eval();
    loc.K.template middleRows<dim>(o) = (q.transpose() * loc.K.template middleRows<dim>(o)).eval();
    loc.b.template segment<dim>(o) = (q.transpose() * loc.b.template segment<dim>(o)).eval();
  };
  for (int k = 0; k <= dim; ++k) {
    if (const int v = mesh.cell(t)[k]; space_.is_contact_vertex(v))
      rotate(dim * k, space_.vertex_frame(v));
    if (const int f = mesh.cell_facet(t, k); space_.is_contact_facet(f))
      rotate(dim * (dim + 1) + dim * k, normal_frame<dim>(mesh.facet_normal(f)));
  }
}

template <int dim>
AssembledProblem FoslsAssembler<dim>::assemble_system(const Deadline& deadline) const {
  const int n_free = space_.num_free();
  AssembledProblem out;
  out.stress_scale = mu_;
  out.vertex_gap = vertex_gap_;
  Vector xd = essential_values();
  AssemblyPattern pattern = assembly_pattern(space_, omp_get_max_threads(), deadline);
  Vector b = Vector::Zero(n_free);
  out.qp.constant = scatter_local_systems<FoslsSpace<dim>>(
      space_, pattern, xd, b,
      [this](int t, Local& loc) {
        element_kernel(t, loc);
        rotate_local(t, loc);
      },
      ConstantSum::kPerThread, deadline);
  add_contact_terms(xd, pattern.matrix, b);
  if constexpr (dim == 2) add_friction_coupling(xd, pattern.matrix, b);
  out.qp.A.swap(pattern.matrix);  // Eigen 3.4's SparseMatrix has no move: std::move would copy
  out.qp.b = std::move(b);
  out.qp.lower = Vector::Constant(n_free, -kNoBound);
  out.qp.upper = Vector::Constant(n_free, kNoBound);
  set_contact_bounds(out.qp.upper);
  if constexpr (dim == 2) {
    out.friction = friction_layout(space_, data_, xd, out.kinks);
    if (!out.friction.empty()) {
      set_friction_bounds(out.friction, Vector::Zero(n_free), out.qp, out.kinks);
      for (const FrictionEdge& f : out.friction.edges) out.qp.row_obstacles.push_back(f.st);
      out.qp.row_obstacles.insert(out.qp.row_obstacles.end(), out.kinks.dof.begin(),
                                  out.kinks.dof.end());
    }
  }
  out.fixed_values = std::move(xd);
  return out;
}

template <int dim>
Vector FoslsAssembler<dim>::essential_values() const {
  const SimplexMesh<dim>& mesh = space_.mesh();
  Vector xd = Vector::Zero(space_.num_dofs());
  set_dirichlet_values(xd);
  for (int f = 0; f < mesh.num_facets(); ++f)
    if (const int g = mesh.facet_group(f); g >= 0 && data_.groups[g].role == GroupRole::kNeumann)
      set_neumann_values(f, data_.groups[g], xd);
  // Dirichlet vertices at the end of a Neumann facet keep their displacement; fixed σ of
  // Neumann facets keep the flux. Clear values of DOFs that are not fixed.
  for (int d = 0; d < space_.num_dofs(); ++d)
    if (!space_.fixed(d)) xd[d] = 0.0;
  return xd;
}

template <int dim>
void FoslsAssembler<dim>::set_dirichlet_values(Vector& xd) const {
  const SimplexMesh<dim>& mesh = space_.mesh();
  constexpr int every = (1 << dim) - 1;
  std::vector<char> held(mesh.num_vertices(), 0);  ///< by a group prescribing every component
  for (int pass = 0; pass < 2; ++pass)
    for (int f = 0; f < mesh.num_facets(); ++f) {
      const int g = mesh.facet_group(f);
      if (g < 0 || data_.groups[g].role != GroupRole::kDirichlet) continue;
      const GroupData<dim>& gd = data_.groups[g];
      const int bits = gd.prescribed & every;
      if ((pass == 0) != (bits == every)) continue;  // full groups first, then rollers
      for (int v : mesh.facet(f)) {
        if (pass == 1 && held[v]) continue;  // a full Dirichlet group's data win
        held[v] |= pass == 0;
        for (int c = 0; c < dim; ++c) {
          if (!(bits & (1 << c))) continue;
          const double value = gd.values[c] ? evaluate<dim>(gd.values[c], mesh.vertex(v)) : 0.0;
          if (!space_.is_contact_vertex(v)) {
            xd[space_.u_dof(v, c)] = value;
            continue;
          }
          // A roller through the contact zone: its axis is a tangent of the vertex's frame
          // (contact_frame.hpp), so the fixed rotated DOF is U_tk = t_k·u = t_k[c] u_c.
          const Mat<dim>& q = space_.vertex_frame(v);
          for (int k = 1; k < dim; ++k)
            if (std::abs(q(c, k)) > 0.5) xd[space_.u_dof(v, k)] = q(c, k) * value;
        }
      }
    }
}

template <int dim>
void FoslsAssembler<dim>::set_neumann_values(int f, const GroupData<dim>& g, Vector& xd) const {
  const SimplexMesh<dim>& mesh = space_.mesh();
  const FacetQuadrature<dim> rule = facet_quadrature<dim>(mesh, f);
  // A normal pressure p is the traction t = −p n with the facet's outward normal n.
  const Vec<dim> n = mesh.facet_normal(f);
  for (int c = 0; c < dim; ++c) {
    const ScalarFunctionOf<dim>& t = g.normal_pressure ? g.values[0] : g.values[c];
    const double factor = g.normal_pressure ? -n[c] : 1.0;
    double flux = 0.0;
    if (t)
      for (std::size_t q = 0; q < rule.points.size(); ++q)
        flux += rule.weights[q] * evaluate<dim>(t, rule.points[q]);
    xd[space_.sigma_dof(f, c)] = factor * flux * mesh.facet_measure(f) / mu_;
  }
}

template <int dim>
void FoslsAssembler<dim>::couple_flux_with_vertex(int s, int v, int component, const Vec<dim>& d,
                                                  double weight, const Vector& xd, SparseMatrix& a,
                                                  Vector& b) const {
  auto couple = [&](int dof, double value) {
    if (value == 0.0) return;
    if (const int fj = space_.free_index(dof); fj >= 0) {
      a.valuePtr()[entry_position(a, s, fj)] += value;
      a.valuePtr()[entry_position(a, fj, s)] += value;
    } else {
      b[s] -= value * xd[dof];  // a fixed displacement's part is known
    }
  };
  if (space_.is_contact_vertex(v))
    couple(space_.u_dof(v, component), weight);
  else
    for (int c = 0; c < dim; ++c) couple(space_.u_dof(v, c), weight * d[c]);
}

template <int dim>
void FoslsAssembler<dim>::add_contact_terms(const Vector& xd, SparseMatrix& a, Vector& b) const {
  const SimplexMesh<dim>& mesh = space_.mesh();
  // Contact term C3 ⟨u·n − g, σ_nn⟩ on each contact facet: σ_nn = S_n/|f| is constant, u·n and
  // g are linear on the facet, so the term is C3 S_n Σ_v ((u·n)_v − g_v) / d over its d
  // vertices (u·n = U_n at a contact vertex, n_f·u at a Dirichlet one). Its entries couple DOFs
  // of the facet's cell, so they are in the pattern.
  const double c3 = data_.weights.c3;
  if (c3 == 0.0) return;
  for (int f = 0; f < mesh.num_facets(); ++f) {
    if (!space_.is_contact_facet(f)) continue;
    const int sn = space_.free_index(space_.sigma_dof(f, 0));
    const Vec<dim> n = mesh.facet_normal(f);
    double gap_sum = 0.0;
    for (int v : mesh.facet(f)) {
      gap_sum += vertex_gap_[v];
      couple_flux_with_vertex(sn, v, 0, n, c3 / dim, xd, a, b);
    }
    b[sn] += c3 * gap_sum / dim;
  }
}

template <int dim>
void FoslsAssembler<dim>::add_friction_coupling(const Vector& xd, SparseMatrix& a, Vector& b) const
    requires(dim == 2) {
  const Mesh& mesh = space_.mesh();
  // C3 ⟨u·t − o, σ_nt⟩ on each frictional edge, o the reference state's u·t: σ_nt = S_t/|e|,
  // u·t linear along the edge (U_t at a contact vertex, t_e·u elsewhere), so the term is
  // C3 S_t ((u·t)_p + (u·t)_q − o_p − o_q) / 2.
  const double c3 = data_.weights.c3;
  if (c3 == 0.0) return;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!space_.is_contact_edge(e) || space_.role(space_.sigma_dof(e, 1)) != DofRole::kTangentialS)
      continue;
    const int st = space_.free_index(space_.sigma_dof(e, 1));
    const Point ne = mesh.edge_normal(e), te(-ne.y(), ne.x());
    double obar = 0.0;
    for (int v : mesh.edge(e)) {
      const Point n = space_.is_contact_vertex(v) ? space_.vertex_normal(v) : ne;
      obar += 0.5 * reference_slip_origin(data_, v, Point(-n.y(), n.x()));
      couple_flux_with_vertex(st, v, 1, te, c3 / 2, xd, a, b);
    }
    b[st] += c3 * obar;
  }
}

template <int dim>
void FoslsAssembler<dim>::set_contact_bounds(Vector& upper) const {
  for (int f = 0; f < space_.num_free(); ++f) {
    const int d = space_.free_to_full()[f];
    if (space_.role(d) == DofRole::kNormalU) upper[f] = vertex_gap_[d / dim];
    if (space_.role(d) == DofRole::kNormalS) upper[f] = 0.0;
  }
}

Vector full_from_free(const Vector& fixed_values, const std::vector<int>& free_to_full,
                      const Vector& x_free) {
  Vector x = fixed_values;
  for (std::size_t f = 0; f < free_to_full.size(); ++f) x[free_to_full[f]] = x_free[f];
  return x;
}

template <int dim>
Vector FoslsAssembler<dim>::full_vector(const AssembledProblem& p, const Vector& x_free) const {
  return full_from_free(p.fixed_values, space_.free_to_full(), x_free);
}

template <int dim>
double FoslsAssembler<dim>::facet_mean_penetration(const Vector& x_full, int f) const {
  const SimplexMesh<dim>& mesh = space_.mesh();
  const Vec<dim> n = mesh.facet_normal(f);
  double penetration = 0.0;
  for (int v : mesh.facet(f)) {
    double un = 0.0;
    if (space_.is_contact_vertex(v)) {
      un = x_full[space_.u_dof(v, 0)];
    } else {
      for (int c = 0; c < dim; ++c) un += n[c] * x_full[space_.u_dof(v, c)];
    }
    penetration += (un - vertex_gap_[v]) / dim;
  }
  return penetration;
}

template <int dim>
FunctionalParts FoslsAssembler<dim>::functional(const Vector& x_full) const {
  const SimplexMesh<dim>& mesh = space_.mesh();
  const FunctionalWeights& w = data_.weights;
  const Vector x_cart = space_.rotation() * x_full;
  constexpr int n = FoslsSpace<dim>::kCellDofs;
  FunctionalParts parts;
  parts.element.assign(mesh.num_cells(), 0.0);
  double mom = 0, con = 0, asym = 0;
#pragma omp parallel for reduction(+ : mom, con, asym) schedule(static)
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SimplexElement<dim> e(mesh, t);
    const auto points = e.quadrature_points();
    const auto dofs = space_.cell_dofs(t);
    Eigen::Matrix<double, n, 1> xl;
    for (int i = 0; i < n; ++i) xl[i] = x_cart[dofs[i]];
    const double wq = e.quadrature_weight();
    const Vec<dim> div = divergence_operator<dim>(e) * xl;
    double m = 0, c = 0, a = 0;
    for (int q = 0; q <= dim; ++q) {
      const PointOperators<dim> op = point_operators<dim>(e, points[q], kappa_);
      m += w.c1 * wq * (div + body_force(t, q)).squaredNorm();
      c += w.c2 * wq * (op.constitutive * xl).squaredNorm();
      if (w.c2_volumetric != 1.0)
        c += w.c2 * wq * (w.c2_volumetric - 1.0) / dim *
             std::pow(volumetric_row<dim>(op).dot(xl), 2);
      a += w.c4 * wq * asymmetry_square(op, xl);
    }
    parts.element[t] = m + c + a;
    mom += m, con += c, asym += a;
  }
  parts.momentum = mom, parts.constitutive = con, parts.asymmetry = asym;
  for (int f = 0; f < mesh.num_facets(); ++f) {
    if (!space_.is_contact_facet(f)) continue;
    const double term = w.c3 * x_full[space_.sigma_dof(f, 0)] * facet_mean_penetration(x_full, f);
    parts.contact += term;
    parts.element[mesh.facet_cells(f)[0]] += term;
  }
  return parts;
}

template class FoslsAssembler<2>;
template class FoslsAssembler<3>;

}  // namespace fosls
