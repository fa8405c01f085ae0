#include "mesher/gmsh_session.hpp"

#include <gmsh.h>

namespace fosls {

std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

void ensure_gmsh_initialized() {
  // Guarded by gmsh_mutex(), held by the caller; never finalised: other threads may mesh until
  // the process exits.
  static bool initialized = false;
  if (initialized) return;
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  gmsh::option::setNumber("General.Terminal", 0);
  initialized = true;
}

}  // namespace fosls
