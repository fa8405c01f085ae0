#pragma once
// Large response bodies (solution VTU files of many megabytes) sent without cpp-httplib's own
// compression: with brotli support built in, cpp-httplib 0.11.4 answers a browser
// (Accept-Encoding: br) at brotli quality 11, which takes minutes on a large VTU; gzip at
// level 1 (gzip.hpp) a fraction of a second (measurements: docs/service.md, "Storage").

#include <httplib.h>

#include <string>

namespace fosls::service {

/// Sets `body` as the response with `content_type`: gzip-encoded (Content-Encoding: gzip) when
/// the request's Accept-Encoding names gzip, as it is otherwise; never re-encoded by the server.
void set_large_body(const httplib::Request& req, httplib::Response& res, std::string body,
                    const std::string& content_type);

}  // namespace fosls::service
