#include "assembly/tet_assembler.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "assembly/assembly_pattern.hpp"
#include "fem/contact_frame.hpp"
#include "fem/simplex_element.hpp"

namespace fosls {

using Mat24 = Eigen::Matrix<double, 24, 24>;
using Vec24 = Eigen::Matrix<double, 24, 1>;
using Row24 = Eigen::Matrix<double, 1, 24>;

struct TetAssembler::Local {
  Mat24 K;
  Vec24 b;
  double c = 0.0;
};

namespace {

/// The functional's operators at one point of a tetrahedron on its 24 DOFs (u: 3k + c, σ:
/// 12 + 3k + i), μ = 1.
struct PointOperators {
  Eigen::Matrix<double, 9, 24> constitutive;  ///< rows 3i + j of Aσ − ε(u)
  Eigen::Matrix<double, 3, 24> asymmetry;     ///< σ_01 − σ_10, σ_02 − σ_20, σ_12 − σ_21
};

PointOperators point_operators(const SimplexElement<3>& e, const Point3& x, double kappa) {
  PointOperators op;
  op.constitutive.setZero();
  op.asymmetry.setZero();
  for (int k = 0; k < 4; ++k) {
    const Point3 psi = e.rt0(k, x);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        // Aσ = (σ − κ tr σ I) / (2μ);  −ε(u) = −½(∇u + ∇uᵀ).
        op.constitutive(3 * i + j, 12 + 3 * k + i) += 0.5 * psi[j];
        if (i == j)
          for (int m = 0; m < 3; ++m)
            op.constitutive(4 * i, 12 + 3 * k + m) -= 0.5 * kappa * psi[m];
        op.constitutive(3 * i + j, 3 * k + i) -= 0.5 * e.grad[k][j];
        op.constitutive(3 * i + j, 3 * k + j) -= 0.5 * e.grad[k][i];
      }
    const std::array<std::array<int, 2>, 3> pairs = {{{0, 1}, {0, 2}, {1, 2}}};
    for (int p = 0; p < 3; ++p) {
      const auto [i, j] = pairs[p];
      op.asymmetry(p, 12 + 3 * k + i) += psi[j];
      op.asymmetry(p, 12 + 3 * k + j) -= psi[i];
    }
  }
  return op;
}

Eigen::Matrix<double, 3, 24> divergence_operator(const SimplexElement<3>& e) {
  Eigen::Matrix<double, 3, 24> d = Eigen::Matrix<double, 3, 24>::Zero();
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) d(i, 12 + 3 * k + i) = e.rt0_div(k);
  return d;
}

Eigen::Vector3d evaluate(const std::array<ScalarFunction3, 3>& f, const Point3& x, double scale) {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = f[i] ? f[i](x) / scale : 0.0;
  return v;
}

}  // namespace

TetAssembler::TetAssembler(const FoslsSpace<3>& space, const TetProblemData& data)
    : space_(space), data_(data) {
  mu_ = data.material.mu;
  if (!(mu_ > 0)) throw std::invalid_argument("mu must be positive");
  const double lambda = data.material.lambda / mu_;
  kappa_ = data.material.incompressible() ? 1.0 / 3.0 : lambda / (3.0 * lambda + 2.0);
  const TetMesh& mesh = space.mesh();
  // Gaps capped at a length far beyond the body, as in 2D: a ray that misses the obstacle leaves
  // its vertex effectively unconstrained, and the functional's gap term stays finite.
  const double far = 10.0 * mesh.diameter();
  vertex_gap_.assign(mesh.num_vertices(), std::numeric_limits<double>::infinity());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (!space.is_contact_facet(f)) continue;
    const TetProblemData::Group& group = data.groups[mesh.face_group(f)];
    for (int v : mesh.face(f)) {
      double g = group.gap ? group.gap(mesh.vertex(v)) : 0.0;
      if (group.gap_along_normal) {  // a Dirichlet vertex has no frame: its face's normal
        const Point3 n =
            space.is_contact_vertex(v) ? Point3(space.vertex_frame(v).col(0)) : mesh.face_normal(f);
        g = group.gap_along_normal(mesh.vertex(v), n);
      }
      if (!std::isfinite(g) || g > far) g = far;
      vertex_gap_[v] = std::min(vertex_gap_[v], g);
    }
  }
}

void TetAssembler::rotate_local(int t, Local& loc) const {
  const TetMesh& mesh = space_.mesh();
  auto rotate = [&loc](int o, const Eigen::Matrix3d& q) {
    loc.K.middleCols<3>(o) = (loc.K.middleCols<3>(o) * q).eval();
    loc.K.middleRows<3>(o) = (q.transpose() * loc.K.middleRows<3>(o)).eval();
    loc.b.segment<3>(o) = (q.transpose() * loc.b.segment<3>(o)).eval();
  };
  for (int k = 0; k < 4; ++k) {
    if (const int v = mesh.tet(t)[k]; space_.is_contact_vertex(v))
      rotate(3 * k, space_.vertex_frame(v));
    if (const int f = mesh.tet_face(t, k); space_.is_contact_facet(f))
      rotate(12 + 3 * k, normal_frame<3>(mesh.face_normal(f)));
  }
}

std::vector<std::pair<int, double>> TetAssembler::contact_couplings(int f) const {
  const TetMesh& mesh = space_.mesh();
  const double c3 = data_.weights.c3 / 3.0;  // the mean of u·n over the face, times |f| σ_nn = S_n
  std::vector<std::pair<int, double>> out;
  for (int v : mesh.face(f)) {
    if (space_.is_contact_vertex(v)) {
      out.emplace_back(space_.u_dof(v, 0), c3);
    } else {
      for (int c = 0; c < 3; ++c) out.emplace_back(space_.u_dof(v, c), c3 * mesh.face_normal(f)[c]);
    }
  }
  return out;
}

double TetAssembler::contact_gap_term(int f) const {
  double g = 0.0;
  for (int v : space_.mesh().face(f)) g += vertex_gap_[v];
  return data_.weights.c3 * g / 3.0;
}

void TetAssembler::element_kernel(int t, Local& out) const {
  const FunctionalWeights& w = data_.weights;
  const SimplexElement<3> e(space_.mesh(), t);
  const auto div = divergence_operator(e);
  const double wq = 0.25 * e.measure;
  out.K.setZero();
  out.b.setZero();
  out.c = 0.0;
  for (const Point3& x : e.quadrature_points()) {
    const PointOperators op = point_operators(e, x, kappa_);
    out.K.noalias() += (2.0 * w.c2 * wq) * op.constitutive.transpose() * op.constitutive;
    if (w.c2_volumetric != 1.0) {
      // |R|² = |dev R|² + ⅓ (tr R)²: the volumetric part re-weighted (docs/method.md §2.2).
      const Row24 trace = op.constitutive.row(0) + op.constitutive.row(4) + op.constitutive.row(8);
      out.K.noalias() +=
          (2.0 * w.c2 * wq * (w.c2_volumetric - 1.0) / 3.0) * trace.transpose() * trace;
    }
    if (w.c4 != 0.0) out.K.noalias() += (2.0 * w.c4 * wq) * op.asymmetry.transpose() * op.asymmetry;
    const Eigen::Vector3d f = evaluate(data_.body_force, x, mu_);
    out.b.noalias() -= (2.0 * w.c1 * wq) * div.transpose() * f;
    out.c += w.c1 * wq * f.squaredNorm();
  }
  out.K.noalias() += (2.0 * w.c1 * e.measure) * div.transpose() * div;
}

Vector TetAssembler::essential_values() const {
  const TetMesh& mesh = space_.mesh();
  Vector xd = Vector::Zero(space_.num_dofs());
  std::vector<char> held(mesh.num_vertices(), 0);  ///< by a group prescribing all components
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int g = mesh.face_group(f);
    if (g < 0) continue;
    const TetProblemData::Group& gd = data_.groups[g];
    const auto& v = mesh.face(f);
    if (gd.role == GroupRole::kDirichlet) {
      if (gd.prescribed != 7) continue;  // rollers, below
      for (int a : v) {
        xd.segment<3>(space_.u_dof(a, 0)) = evaluate(gd.values, mesh.vertex(a), 1.0);
        held[a] = 1;
      }
    } else {
      // ∫_f t dA by the edge-midpoint rule (exact for degree 2), in units of μ.
      Eigen::Vector3d flux = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        const Point3 m = 0.5 * (mesh.vertex(v[k]) + mesh.vertex(v[(k + 1) % 3]));
        flux += gd.normal_pressure ? Eigen::Vector3d(-gd.values[0](m) / mu_ * mesh.face_normal(f))
                                   : evaluate(gd.values, m, mu_);
      }
      xd.segment<3>(space_.sigma_dof(f, 0)) = flux * mesh.face_area(f) / 3.0;
    }
  }
  set_roller_values(held, xd);
  for (int d = 0; d < space_.num_dofs(); ++d)
    if (!space_.fixed(d)) xd[d] = 0.0;
  return xd;
}

void TetAssembler::set_roller_values(const std::vector<char>& held, Vector& xd) const {
  const TetMesh& mesh = space_.mesh();
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int g = mesh.face_group(f);
    if (g < 0 || data_.groups[g].role != GroupRole::kDirichlet || data_.groups[g].prescribed == 7)
      continue;
    const TetProblemData::Group& gd = data_.groups[g];
    for (int a : mesh.face(f)) {
      if (held[a]) continue;  // a full Dirichlet group's data win
      const Eigen::Vector3d u = evaluate(gd.values, mesh.vertex(a), 1.0);
      for (int c = 0; c < 3; ++c) {
        if (!(gd.prescribed & (1 << c))) continue;
        if (!space_.is_contact_vertex(a)) {
          xd[space_.u_dof(a, c)] = u[c];
          continue;
        }
        // On the contact boundary the prescribed axes are the frame's tangents (roller_frame):
        // the fixed U_tk = t_k·u = t_k[c] u_c.
        const Eigen::Matrix3d& q = space_.vertex_frame(a);
        for (int k = 1; k < 3; ++k)
          if (std::abs(q(c, k)) > 0.5) xd[space_.u_dof(a, k)] = q(c, k) * u[c];
      }
    }
  }
}

TetAssembledProblem TetAssembler::assemble_system() const {
  const TetMesh& mesh = space_.mesh();
  const int n = space_.num_free();
  TetAssembledProblem out;
  out.stress_scale = mu_;
  const Vector xd = essential_values();
  // Pattern first, values in place (no 24² triplets per tetrahedron); the contact couplings lie
  // within the contact face's tetrahedron, so in the pattern.
  SparseMatrix a = cell_pattern(n, mesh.num_tets(), [this](int t) {
    std::array<int, 24> free;
    const auto dofs = space_.cell_dofs(t);
    for (int i = 0; i < 24; ++i) free[i] = space_.free_index(dofs[i]);
    return free;
  });
  double* values = a.valuePtr();
  Vector b = Vector::Zero(n);
  double c = 0.0;
  Local loc;
  for (int t = 0; t < mesh.num_tets(); ++t) {
    element_kernel(t, loc);
    rotate_local(t, loc);
    const auto dofs = space_.cell_dofs(t);
    c += loc.c;
    for (int i = 0; i < 24; ++i) {
      const int fi = space_.free_index(dofs[i]);
      if (fi < 0) {
        const double xi = xd[dofs[i]];
        c -= loc.b[i] * xi;
        for (int j = 0; j < 24; ++j)
          if (space_.free_index(dofs[j]) < 0) c += 0.5 * loc.K(i, j) * xi * xd[dofs[j]];
        continue;
      }
      double bi = loc.b[i];
      for (int j = 0; j < 24; ++j) {
        const int fj = space_.free_index(dofs[j]);
        if (fj >= 0)
          values[entry_position(a, fi, fj)] += loc.K(i, j);
        else
          bi -= loc.K(i, j) * xd[dofs[j]];
      }
      b[fi] += bi;
    }
  }
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (!space_.is_contact_facet(f)) continue;
    const int s = space_.free_index(space_.sigma_dof(f, 0));
    b[s] += contact_gap_term(f);
    for (const auto& [dof, value] : contact_couplings(f)) {
      if (const int fu = space_.free_index(dof); fu >= 0) {
        values[entry_position(a, s, fu)] += value;
        values[entry_position(a, fu, s)] += value;
      } else {
        b[s] -= value * xd[dof];
      }
    }
  }
  out.qp.A.swap(a);
  out.qp.b = std::move(b);
  out.qp.constant = c;
  out.qp.lower = Vector::Constant(n, -kNoBound);
  out.qp.upper = Vector::Constant(n, kNoBound);
  for (int i = 0; i < n; ++i) {
    const int d = space_.free_to_full()[i];
    if (space_.role(d) == DofRole::kNormalU) out.qp.upper[i] = vertex_gap_[d / 3];
    if (space_.role(d) == DofRole::kNormalS) out.qp.upper[i] = 0.0;
  }
  out.fixed_values = xd;
  return out;
}

Vector TetAssembler::full_vector(const TetAssembledProblem& p, const Vector& x_free) const {
  return full_from_free(p.fixed_values, space_.free_to_full(), x_free);
}

FunctionalParts TetAssembler::functional(const Vector& x_full) const {
  const TetMesh& mesh = space_.mesh();
  const FunctionalWeights& w = data_.weights;
  const Vector x_cart = space_.rotation() * x_full;
  FunctionalParts parts;
  parts.element.assign(mesh.num_tets(), 0.0);
  for (int t = 0; t < mesh.num_tets(); ++t) {
    const SimplexElement<3> e(mesh, t);
    const auto dofs = space_.cell_dofs(t);
    Vec24 xl;
    for (int i = 0; i < 24; ++i) xl[i] = x_cart[dofs[i]];
    const Eigen::Vector3d div = divergence_operator(e) * xl;
    double m = 0, c = 0, as = 0;
    for (const Point3& x : e.quadrature_points()) {
      const PointOperators op = point_operators(e, x, kappa_);
      const double wq = 0.25 * e.measure;
      m += w.c1 * wq * (div + evaluate(data_.body_force, x, mu_)).squaredNorm();
      const Eigen::Matrix<double, 9, 1> r = op.constitutive * xl;
      c += w.c2 * wq * r.squaredNorm();
      if (w.c2_volumetric != 1.0)
        c += w.c2 * wq * (w.c2_volumetric - 1.0) / 3.0 * std::pow(r[0] + r[4] + r[8], 2);
      as += w.c4 * wq * (op.asymmetry * xl).squaredNorm();
    }
    parts.element[t] = m + c + as;
    parts.momentum += m, parts.constitutive += c, parts.asymmetry += as;
  }
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (!space_.is_contact_facet(f)) continue;
    const double sn = x_full[space_.sigma_dof(f, 0)];
    double term = -contact_gap_term(f) * sn;
    for (const auto& [dof, value] : contact_couplings(f)) term += value * x_full[dof] * sn;
    parts.contact += term;
    parts.element[mesh.face_tets(f)[0]] += term;
  }
  return parts;
}

Point3 TetAssembler::contact_force(const Vector& x_full) const {
  const TetMesh& mesh = space_.mesh();
  Point3 force = Point3::Zero();
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (space_.is_contact_facet(f))
      force += normal_frame<3>(mesh.face_normal(f)) * x_full.segment<3>(space_.sigma_dof(f, 0));
  return mu_ * force;
}

std::vector<double> TetAssembler::contact_pressure(const Vector& x_full) const {
  const TetMesh& mesh = space_.mesh();
  std::vector<double> p(mesh.num_faces(), 0.0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (space_.is_contact_facet(f))
      p[f] = -mu_ * x_full[space_.sigma_dof(f, 0)] / mesh.face_area(f);
  return p;
}

}  // namespace fosls
