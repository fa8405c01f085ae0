#pragma once
// A case's discretisation built as the case runner builds it (coarse mesh, length scale, problem
// data, uniform refinements, c3 "auto"), for tests and benchmarks that drive the solvers
// themselves.
#include <memory>
#include <utility>

#include "assembly/contact_weight.hpp"
#include "assembly/discretization.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_problem_data.hpp"
#include "case/run/mesh_factory.hpp"
#include "mesh/length_scale.hpp"
#include "mesh/refinement.hpp"

namespace fosls::testing {

/// On the heap: the level hierarchy built from it refers to it. Sets spec's length scale.
inline std::unique_ptr<Discretization<2>> case_discretization(CaseSpec& spec) {
  Mesh coarse = build_coarse_mesh(spec.mesh);
  spec.weights.length_scale = length_scale(coarse);
  ProblemData<2> data = problem_data<2>(spec, coarse);
  MeshHierarchy meshes = build_mesh_hierarchy(std::move(coarse), spec.mesh.refinements);
  if (spec.weights.c3_auto)
    data.weights.c3 = automatic_contact_weight(contact_weight_limit(meshes, data));
  return std::make_unique<Discretization<2>>(std::move(meshes), data);
}

}  // namespace fosls::testing
