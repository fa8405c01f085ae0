#include "request_head.hpp"

#include <cstdio>

namespace fosls::service {

namespace {

/// Empty lines a client may send before its request line (some send one after a body).
constexpr std::size_t kMaxLeadingEmptyLines = 4;

/// RFC 9110 §5.6.2: the characters of a token, which a field name is.
bool is_tchar(unsigned char c) {
  if ((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) return true;
  for (char t : std::string_view("!#$%&'*+-.^_`|~"))
    if (c == static_cast<unsigned char>(t)) return true;
  return false;
}

bool is_control(unsigned char c) { return c < 0x20 || c == 0x7f; }

std::string byte_name(unsigned char c) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02X", c);
  return text;
}

/// A field name for a message: quoted, cut to 64 characters.
std::string quoted(const std::string& name) {
  return "'" + (name.size() > 64 ? name.substr(0, 64) + "…" : name) + "'";
}

}  // namespace

std::size_t RequestHeadScanner::scan(std::string_view bytes) {
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (state_ != State::kReading) return i;
    if (!take(bytes[i])) return state_ == State::kComplete ? i + 1 : i;
  }
  return state_ == State::kReading ? bytes.size() : 0;
}

bool RequestHeadScanner::take(char c) {
  ++line_bytes_;
  if (head_bytes_ + line_bytes_ > limits_.max_head_bytes)
    return reject(431, "the request head (request line and header fields) is longer than " +
                           std::to_string(limits_.max_head_bytes) + " bytes");
  if (in_request_line_ && line_bytes_ > limits_.max_request_line)
    return reject(414, "the request line is longer than " +
                           std::to_string(limits_.max_request_line) + " bytes");
  if (!in_request_line_ && line_bytes_ > limits_.max_field_line)
    return reject(431, (after_colon_ ? "the header field " + quoted(field_name_)
                                     : std::string("a header field line")) +
                           " is longer than " + std::to_string(limits_.max_field_line) + " bytes");
  if (after_cr_) {
    if (c != '\n') return reject(400, "a CR in the request head is not followed by LF");
    after_cr_ = false;
    return end_line();
  }
  if (c == '\r') {
    after_cr_ = true;
    return true;
  }
  if (c == '\n')
    return reject(400, "a line of the request head ends with a bare LF; lines end with CRLF");
  return in_request_line_ ? request_line_byte(c) : field_byte(c);
}

bool RequestHeadScanner::end_line() {
  const std::size_t line = line_bytes_;
  line_bytes_ = 0;
  if (in_request_line_) {
    if (request_line_.empty()) {
      leading_empty_bytes_ += line;
      if (leading_empty_bytes_ > 2 * kMaxLeadingEmptyLines)
        return reject(400, "more than " + std::to_string(kMaxLeadingEmptyLines) +
                               " empty lines before the request line");
      return true;
    }
    head_bytes_ += line;
    in_request_line_ = false;
    return true;
  }
  head_bytes_ += line;
  if (line == 2) {  // the blank line after the fields
    state_ = State::kComplete;
    return false;
  }
  if (!after_colon_)
    return reject(400, "the header line starting " + quoted(field_name_) + " has no colon");
  if (++fields_ > limits_.max_fields)
    return reject(
        431, "the request has more than " + std::to_string(limits_.max_fields) + " header fields");
  field_name_.clear();
  after_colon_ = false;
  return true;
}

bool RequestHeadScanner::request_line_byte(char c) {
  if (is_control(static_cast<unsigned char>(c)))
    return reject(400, "the request line contains the control character " +
                           byte_name(static_cast<unsigned char>(c)));
  request_line_ += c;
  return true;
}

bool RequestHeadScanner::field_byte(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (after_colon_) {
    if (is_control(byte) && c != '\t')
      return reject(400, "the value of the header field " + quoted(field_name_) +
                             " contains the control character " + byte_name(byte));
    return true;
  }
  if (c == ' ' || c == '\t') {
    if (field_name_.empty())
      return reject(400,
                    "a header line starts with whitespace (obsolete line folding, RFC 9112 "
                    "§5.2, is not accepted)");
    return reject(400, "whitespace between the header field name " + quoted(field_name_) +
                           " and its colon (RFC 9112 §5.1 requires 400 for it)");
  }
  if (c == ':') {
    if (field_name_.empty()) return reject(400, "a header field has an empty name");
    after_colon_ = true;
    return true;
  }
  if (!is_tchar(byte))
    return reject(400, "the header field name " + quoted(field_name_ + c) +
                           " contains the character " + byte_name(byte) +
                           ", which field names may not contain");
  field_name_ += c;
  return true;
}

bool RequestHeadScanner::reject(int status, std::string detail) {
  state_ = State::kRejected;
  rejection_ = {status, std::move(detail)};
  return false;
}

}  // namespace fosls::service
