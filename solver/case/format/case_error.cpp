#include "case/format/case_error.hpp"

namespace fosls {

namespace {
std::string summary(const std::vector<CaseError>& errors) {
  std::string s;
  for (std::size_t k = 0; k < errors.size() && k < kSummaryErrors; ++k) {
    const CaseError& e = errors[k];
    if (!s.empty()) s += "; ";
    s += (e.pointer.empty() ? std::string("/") : e.pointer) + ": " + e.detail;
  }
  if (errors.size() > kSummaryErrors)
    s += "; and " + std::to_string(errors.size() - kSummaryErrors) + " more problems";
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

std::string quoted_names(const std::vector<std::string>& names, std::size_t shown) {
  std::string list;
  for (std::size_t k = 0; k < names.size() && k < shown; ++k)
    list += (list.empty() ? "'" : ", '") + names[k] + "'";
  if (names.size() > shown) list += " and " + std::to_string(names.size() - shown) + " more";
  return list;
}

CaseError non_finite_problem(const std::string& what) {
  return {"", what +
                  ": the case's data overflow double precision; give displacements, tractions, "
                  "pressures and the body force of a physical size (a value such as 1e300 "
                  "cannot be squared)"};
}

CaseException::CaseException(std::vector<CaseError> errors)
    : std::runtime_error(summary(errors)), errors_(std::move(errors)) {}

CaseException::CaseException(std::string pointer, std::string detail)
    : CaseException(std::vector<CaseError>{{std::move(pointer), std::move(detail)}}) {}

}  // namespace fosls
