// Pure request checks: media type, JSON depth, ids, idempotency keys, digests.

#include "request_checks.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fosls::service {
namespace {

TEST(RequestChecks, JsonMediaTypeAcceptsParametersAndCase) {
  EXPECT_TRUE(is_json_media_type("application/json"));
  EXPECT_TRUE(is_json_media_type("Application/JSON; charset=utf-8"));
  EXPECT_TRUE(is_json_media_type(" application/json ;charset=UTF-8"));
  EXPECT_FALSE(is_json_media_type(""));
  EXPECT_FALSE(is_json_media_type("application/x-www-form-urlencoded"));
  EXPECT_FALSE(is_json_media_type("text/json"));
  EXPECT_FALSE(is_json_media_type("application/jsonx"));
}

TEST(RequestChecks, NestingDepthIgnoresBracketsInStrings) {
  EXPECT_EQ(json_nesting_depth("1", 64), 0);
  EXPECT_EQ(json_nesting_depth(R"({"a":[1,{"b":2}]})", 64), 3);
  EXPECT_EQ(json_nesting_depth(R"({"a":"[[[[\"[[["})", 64), 1);
  EXPECT_EQ(json_nesting_depth(std::string(1000, '['), 64), 65);  // stops past the limit
}

TEST(RequestChecks, JobIdsArePositiveDecimalIntegers) {
  EXPECT_EQ(parse_job_id("1"), 1);
  EXPECT_EQ(parse_job_id("9223372036854775807"), 9223372036854775807LL);
  EXPECT_FALSE(parse_job_id("0"));
  EXPECT_FALSE(parse_job_id("-1"));
  EXPECT_FALSE(parse_job_id("01"));
  EXPECT_FALSE(parse_job_id("12a"));
  EXPECT_FALSE(parse_job_id(""));
  EXPECT_FALSE(parse_job_id("9223372036854775808"));  // overflow
  EXPECT_FALSE(parse_job_id("99999999999999999999"));
}

TEST(RequestChecks, IdempotencyKeysAreVisibleAscii) {
  EXPECT_TRUE(is_valid_idempotency_key("abc-123_XYZ"));
  EXPECT_FALSE(is_valid_idempotency_key(""));
  EXPECT_FALSE(is_valid_idempotency_key("has space"));
  EXPECT_FALSE(is_valid_idempotency_key(std::string(256, 'k')));
  EXPECT_FALSE(is_valid_idempotency_key("caf\xc3\xa9"));
}

TEST(RequestChecks, ChunkedTransferEncoding) {
  EXPECT_TRUE(is_chunked("chunked"));
  EXPECT_TRUE(is_chunked("gzip, Chunked"));
  EXPECT_FALSE(is_chunked("gzip"));
}

TEST(RequestChecks, Sha256MatchesKnownDigests) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

}  // namespace
}  // namespace fosls::service
