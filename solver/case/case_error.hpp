#pragma once
// A problem with a user's case: where (JSON pointer) and why (a sentence a person can act on).

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
class CaseException : public std::runtime_error {
 public:
  explicit CaseException(std::vector<CaseError> errors);
  CaseException(std::string pointer, std::string detail);
  const std::vector<CaseError>& errors() const { return errors_; }

 private:
  std::vector<CaseError> errors_;
};

}  // namespace fosls
