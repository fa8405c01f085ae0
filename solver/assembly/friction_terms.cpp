#include "assembly/friction_terms.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace fosls {

namespace {

/// ∫_e s/μ by 3-point Gauss–Legendre; s must not be negative.
double tresca_bound(const ScalarFunction& s, const Point& a, const Point& b, double mu) {
  constexpr std::array<double, 3> x = {0.1127016653792583, 0.5, 0.8872983346207417};
  constexpr std::array<double, 3> w = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  double sum = 0.0;
  for (int q = 0; q < 3; ++q) {
    const Point p = a + x[q] * (b - a);
    const double value = s(p.x(), p.y());
    if (!(value >= 0.0)) {
      std::ostringstream m;
      m << "the friction bound is " << value << " at (" << p.x() << ", " << p.y()
        << "); it must be a number >= 0 everywhere on the contact boundary";
      throw std::domain_error(m.str());
    }
    sum += w[q] * value;
  }
  return sum * (b - a).norm() / mu;
}

}  // namespace

double reference_slip_origin(const ProblemData<2>& data, int v, const Point& tangent) {
  // Only the finest level has a reference; the coarser ones the c3 limit assembles need only
  // the matrix, which the reference does not change.
  if (v >= static_cast<int>(data.reference_displacement.size())) return 0.0;
  return tangent.dot(data.reference_displacement[v]);
}

Point slip_tangent(const FoslsSpace<2>& space, int e, int v) {
  const Point n = space.is_contact_vertex(v) ? space.vertex_normal(v) : space.mesh().edge_normal(e);
  return Point(-n.y(), n.x());
}

double tangential_displacement(const FoslsSpace<2>& space, const Vector& x_full, int v,
                               const Point& t) {
  if (space.is_contact_vertex(v)) return x_full[space.u_dof(v, 1)];
  return t.x() * x_full[space.u_dof(v, 0)] + t.y() * x_full[space.u_dof(v, 1)];
}

FrictionLayout friction_layout(const FoslsSpace<2>& space, const ProblemData<2>& data,
                               const Vector& xd, Kinks& kinks) {
  const Mesh& mesh = space.mesh();
  FrictionLayout layout;
  layout.c3 = data.weights.c3;
  std::map<int, int> kink_of;  // free U_t → kink index
  kinks = Kinks{};
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!space.is_contact_edge(e) || space.role(space.sigma_dof(e, 1)) != DofRole::kTangentialS)
      continue;
    const FrictionData<2>& friction = data.groups[mesh.edge_group(e)].contact.friction;
    FrictionEdge f;
    f.edge = e;
    f.st = space.free_index(space.sigma_dof(e, 1));
    f.sn = space.free_index(space.sigma_dof(e, 0));
    f.coefficient = friction.coefficient;
    const auto& pq = mesh.edge(e);
    if (!friction.coulomb())
      f.tresca =
          tresca_bound(friction.bound, mesh.vertex(pq[0]), mesh.vertex(pq[1]), data.material.mu);
    for (int k = 0; k < 2; ++k) {
      const int v = pq[k];
      const Point t = slip_tangent(space, e, v);
      const double origin = reference_slip_origin(data, v, t);
      const int ut = space.is_contact_vertex(v) ? space.free_index(space.u_dof(v, 1)) : -1;
      if (ut >= 0) {
        auto [it, added] = kink_of.try_emplace(ut, kinks.size());
        if (added) {
          kinks.dof.push_back(ut);
          kinks.at.push_back(origin);
          kinks.weight.push_back(0.0);
        }
        f.kink[k] = it->second;
      } else {
        // A fixed tangential displacement: a roller's U_t, or both Dirichlet components.
        f.fixed_slip[k] = tangential_displacement(space, xd, v, t) - origin;
      }
    }
    layout.edges.push_back(f);
  }
  return layout;
}

}  // namespace fosls
