#pragma once
// MeshSpec → coarse Mesh: built-in geometries, declarative geometry through the gmsh API, msh
// text, and (command line only) .geo files.

#include "case/case_spec.hpp"
#include "mesh/mesh.hpp"

namespace fosls {

/// Builds the coarse mesh of a case. Errors a user can cause (corrupt msh, crossing segments,
/// gmsh failures, an unreadable .geo file) are thrown as CaseException with the pointer of
/// the offending field under /mesh. Every gmsh call is made under one process-wide mutex.
Mesh build_coarse_mesh(const MeshSpec& spec);

}  // namespace fosls
