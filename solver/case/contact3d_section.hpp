#pragma once
// The contact condition of a 3D case: its rigid obstacle given as a plane's point and normal (the
// short form) or as `obstacle` — a plane, a sphere or a gap function of x, y and z — and its
// reading into an Obstacle3d.

#include <nlohmann/json.hpp>

#include "case/case3d_spec.hpp"
#include "case/case_reader.hpp"
#include "case/case_rules.hpp"

namespace fosls {

/// The contact variant of a 3D boundary condition.
ObjectVariant contact3d_variant(const CaseReadOptions& options);

/// Three numbers that passed vector3_value's rule, as a point (also the 3D reader's).
Point3 read_vector3(const nlohmann::json& j);

/// The obstacle of a contact condition that passed contact3d_variant's rules.
Obstacle3d read_obstacle3d(const nlohmann::json& condition);

}  // namespace fosls
