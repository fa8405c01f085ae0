#pragma once
// Exit codes of fosls-contact (documented in docs/case-format.md).

namespace fosls {

inline constexpr int kExitOk = 0;            ///< solved and converged, or command done
inline constexpr int kExitInternal = 1;      ///< an unexpected failure (a bug or the system)
inline constexpr int kExitBadInput = 2;      ///< bad command line, unreadable or invalid case
inline constexpr int kExitNotConverged = 3;  ///< solved, but the solver did not converge
/// solved and converged, but a warning says that the answer may be physically empty or wrong
/// (no contact, an initial overlap, ...: the result's review_required); the result is written
inline constexpr int kExitReviewRequired = 4;

}  // namespace fosls
