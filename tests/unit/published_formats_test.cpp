// docs/case-format.md, docs/result-format.md and docs/schemas/*.schema.json say what the code
// does: their generated parts must equal what published_formats.hpp generates from the rules
// the reader checks and every result is checked against.
// To refresh them after changing a rule: FOSLS_UPDATE_DOCS=1 build/bin/published_formats_test

#include "case/format/published_formats.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace fosls {
namespace {

const std::string kDocs = std::string(FOSLS_SOURCE_DIR) + "/docs/";

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

/// The generated blocks of a document equal `blocks`, and every block is in the document.
void check_document(const std::string& file, const std::map<std::string, std::string>& blocks) {
  const std::string path = kDocs + file;
  const std::string doc = read_text(path);
  ASSERT_FALSE(doc.empty()) << path;
  std::string expected = doc;
  std::set<std::string> unknown;
  const auto found = fill_blocks(expected, blocks, unknown);
  for (const auto& name : unknown) ADD_FAILURE() << file << ": nothing generates block " << name;
  for (const auto& [name, text] : blocks)
    EXPECT_TRUE(found.count(name)) << file << " has no block " << name;
  if (updating() && expected != doc) {
    std::ofstream(path, std::ios::binary) << expected;
    GTEST_SKIP() << "rewrote " << path;
  }
  EXPECT_EQ(doc, expected) << file << " differs from the rules; run "
                           << "FOSLS_UPDATE_DOCS=1 build/bin/published_formats_test";
}

void check_schema(const std::string& file, const nlohmann::json& schema) {
  const std::string path = kDocs + "schemas/" + file;
  const std::string expected = schema.dump(2) + "\n";
  const std::string published = read_text(path);
  if (updating() && expected != published) {
    std::ofstream(path, std::ios::binary) << expected;
    GTEST_SKIP() << "rewrote " << path;
  }
  EXPECT_EQ(published, expected) << "docs/schemas/" << file << " differs from the rules; run "
                                 << "FOSLS_UPDATE_DOCS=1 build/bin/published_formats_test";
}

TEST(PublishedFormats, CaseFormatDocMatchesTheRules) {
  check_document("case-format.md", case_format_blocks());
}

TEST(PublishedFormats, ResultFormatDocMatchesTheRules) {
  check_document("result-format.md", result_format_blocks());
}

TEST(PublishedFormats, CaseSchemaMatchesTheRules) {
  check_schema("case.schema.json", case_json_schema());
}

TEST(PublishedFormats, ResultSchemaMatchesTheRules) {
  check_schema("result.schema.json", result_json_schema());
}

TEST(PublishedFormats, Result3dSchemaMatchesTheRules) {
  check_schema("result3d.schema.json", result3d_json_schema());
}

// Every section has a table, so no field can be added to the reader without showing up in the
// docs.
TEST(PublishedFormats, EveryCaseSectionIsInATable) {
  const auto blocks = case_format_blocks();
  for (const char* section : {"case", "mesh", "builtin", "geometry", "curve", "material",
                              "condition", "obstacle", "weights", "solver"})
    EXPECT_TRUE(blocks.count(std::string("fields:") + section)) << section;
  const std::string& solver = blocks.at("fields:solver");
  for (const char* field : {"`method`", "`tolerance`", "`max_iterations`", "`smoother`",
                            "`pre_smoothing`", "`post_smoothing`", "`coarse_obstacle`"})
    EXPECT_NE(solver.find(field), std::string::npos) << field;
  EXPECT_NE(blocks.at("methods").find("`pdas` | —"), std::string::npos) << blocks.at("methods");
  EXPECT_NE(blocks.at("limits").find("coarse triangles"), std::string::npos) << blocks.at("limits");
}

}  // namespace
}  // namespace fosls
