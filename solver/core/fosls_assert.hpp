#pragma once
// FOSLS_ASSERT(condition, message): an invariant of the algorithms (feasibility of every
// iterate, decrease of J in a monotone method, the shapes of a level hierarchy), checked in
// builds with FOSLS_CHECKS defined — Debug builds and the sanitizer configuration
// (`tests/run.sh --sanitize`) — and compiled out otherwise, so the checks may cost O(N) per
// iteration. A failed check throws InvariantError naming the condition, the file and the line:
// it is a bug in the library, never a user's mistake (those are CaseException).

#include <stdexcept>
#include <string>

namespace fosls {

/// A broken invariant of the library (see FOSLS_ASSERT).
class InvariantError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

[[noreturn]] inline void invariant_failed(const char* condition, const std::string& message,
                                          const char* file, int line) {
  throw InvariantError(std::string(file) + ":" + std::to_string(line) + ": " + condition +
                       " does not hold: " + message);
}

/// Whether FOSLS_ASSERT checks anything in this build.
#ifdef FOSLS_CHECKS
constexpr bool kChecksEnabled = true;
#else
constexpr bool kChecksEnabled = false;
#endif

}  // namespace fosls

#ifdef FOSLS_CHECKS
#define FOSLS_ASSERT(condition, message) \
  ((condition) ? void(0) : ::fosls::invariant_failed(#condition, (message), __FILE__, __LINE__))
#else
#define FOSLS_ASSERT(condition, message) ((void)0)
#endif
