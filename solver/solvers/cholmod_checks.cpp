#include "solvers/cholmod_checks.hpp"

#include <new>
#include <stdexcept>
#include <string>

namespace fosls {

void check_cholmod_status(const cholmod_common& common, const char* what) {
  if (common.status == CHOLMOD_OUT_OF_MEMORY || common.status == CHOLMOD_TOO_LARGE)
    throw std::bad_alloc();
  // Positive status values are warnings (not positive definite, a tiny diagonal): the callers
  // read them from info().
  if (common.status < 0)
    throw std::runtime_error(std::string("CHOLMOD failed in ") + what + " (status " +
                             std::to_string(common.status) + ")");
}

}  // namespace fosls
