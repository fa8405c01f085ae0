#include "core/peak_memory.hpp"

#include <sys/resource.h>

namespace fosls {

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // KiB on Linux
}

}  // namespace fosls
