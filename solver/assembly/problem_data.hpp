#pragma once
// The continuous problem handed to the assembler: material, weights, data as functions.

#include <array>
#include <functional>
#include <vector>

#include "case/case_spec.hpp"
#include "fem/fosls_space.hpp"

namespace fosls {

using ScalarFunction = std::function<double(double x, double y)>;

/// Contact data of one group: the rigid obstacle and the constraint direction (docs/method.md §1).
struct ContactData {
  Obstacle obstacle;
  ScalarFunction gap;  ///< for Obstacle::Kind::kGap
  ContactDirection direction = ContactDirection::kBodyNormal;
};

/// Boundary condition of one mesh group.
struct GroupData {
  GroupRole role = GroupRole::kNeumann;
  std::array<ScalarFunction, 2> values;  ///< u_D (Dirichlet) or t_N (Neumann), Cartesian
  ContactData contact;
};

struct ProblemData {
  Material material;
  Weights weights;
  std::array<ScalarFunction, 2> body_force;
  std::vector<GroupData> groups;  ///< indexed like Mesh::group_names()

  std::vector<GroupRole> roles() const {
    std::vector<GroupRole> r;
    for (const auto& g : groups) r.push_back(g.role);
    return r;
  }
};

/// Where the obstacle is seen from a boundary point: the constraint direction d (unit) and the
/// gap g ≥ u·d, measured along d. A point whose ray misses the obstacle gets an infinite gap.
struct ContactPoint {
  Point direction;
  double gap;
};
ContactPoint locate_obstacle(const ContactData& c, const Point& p, const Point& body_normal);

}  // namespace fosls
