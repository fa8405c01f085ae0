#include "large_body.hpp"

#include <algorithm>
#include <memory>

#include "gzip.hpp"

namespace fosls::service {

void set_large_body(const httplib::Request& req, httplib::Response& res, std::string body,
                    const std::string& content_type) {
  res.set_header("Vary", "Accept-Encoding");
  if (req.get_header_value("Accept-Encoding").find("gzip") != std::string::npos) {
    body = gzip_compress(body);
    res.set_header("Content-Encoding", "gzip");
  }
  // A content provider of known length is written as it is: cpp-httplib compresses only bodies
  // set with set_content and chunked providers.
  auto data = std::make_shared<const std::string>(std::move(body));
  res.set_content_provider(data->size(), content_type,
                           [data](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             sink.write(data->data() + offset,
                                        std::min(length, data->size() - offset));
                             return true;
                           });
}

}  // namespace fosls::service
