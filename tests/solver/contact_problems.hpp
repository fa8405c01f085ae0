#pragma once
// The two contact benchmarks as ProblemData, shared by the solver tests.

#include <cmath>

#include "assembly/discretization.hpp"
#include "mesh/builtin_meshes.hpp"

namespace fosls::testing {

/// Unit square pressed down by 0.05 at the top onto a curved gap g = 0.5 (x − ½)² under the
/// bottom: the contact zone is a proper sub-interval of the bottom edge.
inline ProblemData<2> signorini_square(double lambda) {
  ProblemData<2> d;
  d.material.mu = 1.0;
  d.material.lambda = lambda;
  d.groups.resize(4);  // bottom, right, top, left
  d.groups[0].role = GroupRole::kContact;
  d.groups[0].contact.obstacle.kind = RigidObstacle<2>::Kind::kGap;
  d.groups[0].contact.gap = [](double x, double) { return 0.5 * (x - 0.5) * (x - 0.5); };
  d.groups[2].role = GroupRole::kDirichlet;
  d.groups[2].values = {[](double, double) { return 0.0; }, [](double, double) { return -0.05; }};
  d.groups[1].role = d.groups[3].role = GroupRole::kNeumann;
  return d;
}

/// The linear square: pressed by 0.05 onto the flat obstacle y = 0, so that the whole
/// bottom is in contact.
inline ProblemData<2> flat_square(double lambda) {
  ProblemData<2> d = signorini_square(lambda);
  d.groups[0].contact.obstacle.kind = RigidObstacle<2>::Kind::kPlane;
  d.groups[0].contact.obstacle.point = Point(0, 0);
  d.groups[0].contact.obstacle.normal = Point(0, 1);
  return d;
}

/// Half disk of radius 1 pressed onto the plane y = 0 by a displacement of the flat top.
inline ProblemData<2> hertz(double lambda, double press = 0.02) {
  ProblemData<2> d;
  d.material.mu = 1.0;
  d.material.lambda = lambda;
  d.groups.resize(3);  // top, contact, free (order of make_hertz's groups)
  d.groups[0].role = GroupRole::kDirichlet;
  d.groups[0].values = {[](double, double) { return 0.0; },
                        [press](double, double) { return -press; }};
  d.groups[1].role = GroupRole::kContact;
  d.groups[1].contact.obstacle.kind = RigidObstacle<2>::Kind::kPlane;
  d.groups[1].contact.obstacle.point = Point(0, 0);
  d.groups[1].contact.obstacle.normal = Point(0, 1);
  d.groups[2].role = GroupRole::kNeumann;
  return d;
}

}  // namespace fosls::testing
