#include "memory_budget.hpp"

#include <algorithm>

namespace fosls::service {

std::size_t default_job_memory(int workers) {
  return static_cast<std::size_t>(0.75 * static_cast<double>(physical_memory()) /
                                  std::max(1, workers));
}

}  // namespace fosls::service
