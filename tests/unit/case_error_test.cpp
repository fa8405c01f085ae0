// Error texts stay bounded however large the input: a list of names in one error shows a
// handful and counts the rest, and an exception's message spells out a bounded number of
// problems (docs/service.md, "Hostile use": one request of 6 000 unknown group names against a
// mesh of 20 000 groups once built a 660 MB answer).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/admission/early_group_check.hpp"
#include "case/format/case_error.hpp"

namespace fosls {
namespace {

std::vector<std::string> names(int n) {
  std::vector<std::string> out;
  for (int k = 0; k < n; ++k) out.push_back("group_" + std::to_string(k));
  return out;
}

TEST(CaseErrorText, AShortListIsWrittenWholeALongOneShowsEightAndCountsTheRest) {
  EXPECT_EQ(quoted_names(names(3)), "'group_0', 'group_1', 'group_2'");
  EXPECT_EQ(quoted_names({}), "");
  const std::string list = quoted_names(names(20000));
  EXPECT_NE(list.find("'group_7' and 19992 more"), std::string::npos) << list;
  EXPECT_EQ(list.find("group_8'"), std::string::npos) << list;
}

TEST(CaseErrorText, AnUnknownGroupAgainstTwentyThousandGroupsIsOneShortSentence) {
  const CaseError e = unknown_group_problem("nope", names(20000));
  EXPECT_EQ(e.pointer, "/boundary/nope");
  EXPECT_LT(e.detail.size(), 300u) << e.detail;
  EXPECT_NE(e.detail.find("and 19992 more"), std::string::npos) << e.detail;
}

TEST(CaseErrorText, AnExceptionSpellsOutTwentyProblemsAndCountsTheRestButKeepsThemAll) {
  std::vector<CaseError> errors;
  for (int k = 0; k < 5000; ++k) errors.push_back({"/boundary/g" + std::to_string(k), "unknown"});
  const CaseException e(errors);
  EXPECT_EQ(e.errors().size(), 5000u);
  const std::string what = e.what();
  EXPECT_NE(what.find("/boundary/g19: unknown"), std::string::npos);
  EXPECT_EQ(what.find("/boundary/g20:"), std::string::npos);
  EXPECT_NE(what.find("and 4980 more problems"), std::string::npos) << what.substr(0, 100);
}

}  // namespace
}  // namespace fosls
