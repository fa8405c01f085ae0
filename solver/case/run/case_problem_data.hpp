#pragma once
// A validated case in the assembly layer's terms: material, weights (the c1 term in units of
// the body's size), body force and each mesh group's boundary condition as functions.

#include "assembly/problem_data.hpp"
#include "case/format/case_spec.hpp"
#include "mesh/simplex_mesh.hpp"

namespace fosls {

/// `spec.weights` as used (length_scale set, c3 chosen when "auto"); groups indexed like
/// mesh.group_names(), the unnamed ones traction free; in 2D or 3D.
template <int dim>
ProblemData<dim> problem_data(const CaseSpec& spec, const SimplexMesh<dim>& mesh);

/// With c3 "auto" and a contact group: c3 chosen from the definiteness limit on `meshes`
/// (assembly/contact_weight.hpp), set in `data` and recorded in `used.weights` (c3, c3_limit).
template <int dim>
void choose_contact_weight(CaseSpec& used, const SimplexHierarchy<dim>& meshes,
                           ProblemData<dim>& data);

}  // namespace fosls
