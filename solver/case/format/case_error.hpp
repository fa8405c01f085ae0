#pragma once
// A problem with a user's case: where (JSON pointer) and why (a sentence a person can act on).

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace fosls {

struct CaseError {
  std::string pointer;  ///< RFC 6901 JSON pointer of the offending field, "" for the whole case
  std::string detail;   ///< what is wrong and what to do about it
};

/// Thrown by the stages after JSON reading (meshing, DOF limits, indefinite weights) so that
/// the CLI and the service report them exactly like validation errors.
/// The pointer of member `key` of the value at `pointer` (RFC 6901: "~" is written "~0" and "/"
/// is written "~1" inside a reference token).
std::string child_pointer(const std::string& pointer, const std::string& key);
/// The pointer of entry `index` of the array at `pointer`.
std::string child_pointer(const std::string& pointer, std::size_t index);

/// Names for a message, quoted and bounded: the first `shown`, then "and N more". A list in an
/// error grows with the input (a mesh may have 10⁵ groups), and one such list per error made a
/// hostile request's answer quadratic in its size (docs/service.md, "Hostile use").
std::string quoted_names(const std::vector<std::string>& names, std::size_t shown = 8);

/// At most this many problems are spelt out in a CaseException's message (all stay in errors()).
constexpr std::size_t kSummaryErrors = 20;

/// The problem of a solve whose numbers became infinite or NaN (core/non_finite.hpp): said
/// against the case's data, which is where such numbers come from.
CaseError non_finite_problem(const std::string& what);

class CaseException : public std::runtime_error {
 public:
  explicit CaseException(std::vector<CaseError> errors);
  CaseException(std::string pointer, std::string detail);
  const std::vector<CaseError>& errors() const { return errors_; }

 private:
  std::vector<CaseError> errors_;
};

}  // namespace fosls
