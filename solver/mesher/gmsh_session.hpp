#pragma once
// gmsh inside this process. Only the mesher program (and test code that writes reference
// files) calls gmsh in-process: gmsh 4.8 can abort the whole process on degenerate input, so
// the solver, the CLI and the service mesh through fosls-mesher (mesh/gmsh_mesh.hpp).

#include <mutex>

namespace fosls {

/// The one mutex that guards every gmsh call in the process. Hold it for the whole sequence of
/// calls that builds or reads a model: gmsh's current model is global.
std::mutex& gmsh_mutex();

/// Initialises gmsh once per process (no configuration files, no terminal output). The caller
/// must hold gmsh_mutex().
void ensure_gmsh_initialized();

}  // namespace fosls
