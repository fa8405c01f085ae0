// docs/case-format.md and docs/schemas/case.schema.json say what the reader checks: their
// generated parts must equal what case_schema.hpp generates from the reader's rules.
// To refresh them after changing a rule: FOSLS_UPDATE_DOCS=1 build/bin/case_format_docs_test

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "case/case_schema.hpp"

namespace fosls {
namespace {

const std::string kDoc = std::string(FOSLS_SOURCE_DIR) + "/docs/case-format.md";
const std::string kSchema = std::string(FOSLS_SOURCE_DIR) + "/docs/schemas/case.schema.json";

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool updating() {
  const char* v = std::getenv("FOSLS_UPDATE_DOCS");
  return v && std::string(v) == "1";
}

const std::string kBegin = "<!-- generated:";
const std::string kEnd = "<!-- /generated -->";

/// Replaces the body of every generated block of `doc`; returns the names found.
std::set<std::string> fill_blocks(std::string& doc,
                                  const std::map<std::string, std::string>& blocks,
                                  std::set<std::string>& unknown) {
  std::set<std::string> found;
  for (std::size_t at = doc.find(kBegin); at != std::string::npos; at = doc.find(kBegin, at + 1)) {
    const std::size_t name_end = doc.find(" -->\n", at);
    const std::string name = doc.substr(at + kBegin.size(), name_end - at - kBegin.size());
    const std::size_t body = name_end + 5, end = doc.find(kEnd, body);
    if (end == std::string::npos) break;
    auto it = blocks.find(name);
    if (it == blocks.end()) {
      unknown.insert(name);
      continue;
    }
    found.insert(name);
    doc.replace(body, end - body, it->second);
  }
  return found;
}

TEST(CaseFormatDocs, GeneratedBlocksMatchTheRules) {
  const auto blocks = case_format_blocks();
  const std::string doc = read_text(kDoc);
  ASSERT_FALSE(doc.empty()) << kDoc;
  std::string expected = doc;
  std::set<std::string> unknown;
  const auto found = fill_blocks(expected, blocks, unknown);
  EXPECT_TRUE(unknown.empty()) << "blocks in the doc that nothing generates: " << *unknown.begin();
  for (const auto& [name, text] : blocks)
    EXPECT_TRUE(found.count(name)) << "docs/case-format.md has no block " << name;
  if (updating() && expected != doc) {
    std::ofstream(kDoc, std::ios::binary) << expected;
    GTEST_SKIP() << "rewrote " << kDoc;
  }
  EXPECT_EQ(doc, expected) << "docs/case-format.md differs from the rules; run "
                              "FOSLS_UPDATE_DOCS=1 build/bin/case_format_docs_test";
}

TEST(CaseFormatDocs, PublishedSchemaMatchesTheRules) {
  const std::string expected = case_json_schema().dump(2) + "\n";
  const std::string published = read_text(kSchema);
  if (updating() && expected != published) {
    std::ofstream(kSchema, std::ios::binary) << expected;
    GTEST_SKIP() << "rewrote " << kSchema;
  }
  EXPECT_EQ(published, expected) << "docs/schemas/case.schema.json differs from the rules; run "
                                    "FOSLS_UPDATE_DOCS=1 build/bin/case_format_docs_test";
}

// Every field of every section appears in a generated table, so no field can be added to the
// reader without showing up in the docs.
TEST(CaseFormatDocs, EveryFieldIsInATable) {
  const auto blocks = case_format_blocks();
  for (const char* section : {"case", "mesh", "builtin", "geometry", "curve", "material",
                              "condition", "obstacle", "weights", "solver"})
    EXPECT_TRUE(blocks.count(std::string("fields:") + section)) << section;
  const std::string& solver = blocks.at("fields:solver");
  for (const char* field : {"`method`", "`tolerance`", "`max_iterations`", "`smoother`",
                            "`pre_smoothing`", "`post_smoothing`", "`coarse_obstacle`"})
    EXPECT_NE(solver.find(field), std::string::npos) << field;
  EXPECT_NE(blocks.at("methods").find("`pdas` | —"), std::string::npos) << blocks.at("methods");
  EXPECT_NE(blocks.at("limits").find("200 000"), std::string::npos) << blocks.at("limits");
}

}  // namespace
}  // namespace fosls
