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

std::string child_pointer(const std::string& pointer, const std::string& key) {
  std::string out = pointer + "/";
  out.reserve(out.size() + key.size());
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string child_pointer(const std::string& pointer, std::size_t index) {
  return pointer + "/" + std::to_string(index);
}

CaseException::CaseException(std::vector<CaseError> errors)
    : std::runtime_error(summary(errors)), errors_(std::move(errors)) {}

CaseException::CaseException(std::string pointer, std::string detail)
    : CaseException(std::vector<CaseError>{{std::move(pointer), std::move(detail)}}) {}

}  // namespace fosls
