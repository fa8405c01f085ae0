#pragma once
// MeshSpec → coarse Mesh: built-in geometries, declarative geometry and .geo files (meshed by
// gmsh in the mesher process), and msh text. The one place where the mesh layer's errors
// (MeshError, fields relative to the mesh section) become CaseException with JSON pointers
// under /mesh.

#include <optional>
#include "case/format/case_error.hpp"

#include "case/format/case_spec.hpp"
#include "mesh/builtin_meshes.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "mesh/mesh.hpp"

namespace fosls {

/// Builds the coarse mesh of a case. Errors a user can cause (corrupt msh, crossing segments,
/// gmsh failing, crashing or running out of time or memory, an unreadable .geo file) are
/// thrown as CaseException with the pointer of the offending field under /mesh. Throws
/// MeshingCancelled when `control.cancel` stopped the mesher.
Mesh build_coarse_mesh(const MeshSpec& spec, const MeshingControl& control = {});

/// The outline and size field gmsh would mesh for this source (a geometry, or the built-in
/// hertz), after the parameter checks that need no gmsh; nothing for sources built without gmsh
/// (the built-in square, msh text) or a .geo file. Throws CaseException for bad parameters.
std::optional<GmshOutline> gmsh_outline(const MeshSpec& spec);

/// The JSON pointer of a mesh-layer problem of `spec`: its field prefixed with /mesh; for
/// built-in geometries, problems of the generated outline at /mesh/builtin, the field the
/// user wrote; a declarative geometry's groups by their names (the case's groups object).
std::string mesh_problem_pointer(const MeshProblem& problem, const MeshSpec& spec);

/// The field that gave the mesh ("/mesh/builtin", "/mesh/msh_file", ...): where a problem of
/// the mesh as a whole is reported.
std::string mesh_source_pointer(const MeshSpec& spec);

/// A MeshError of `spec` as the case's problems, at mesh_problem_pointer().
CaseException to_case_exception(const MeshError& error, const MeshSpec& spec);

}  // namespace fosls
