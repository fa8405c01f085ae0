#include "case/case_error.hpp"

namespace fosls {

namespace {
std::string summary(const std::vector<CaseError>& errors) {
  std::string s;
  for (const auto& e : errors) {
    if (!s.empty()) s += "; ";
    s += (e.pointer.empty() ? std::string("/") : e.pointer) + ": " + e.detail;
  }
  return s;
}
}  // namespace

CaseException::CaseException(std::vector<CaseError> errors)
    : std::runtime_error(summary(errors)), errors_(std::move(errors)) {}

CaseException::CaseException(std::string pointer, std::string detail)
    : CaseException(std::vector<CaseError>{{std::move(pointer), std::move(detail)}}) {}

}  // namespace fosls
