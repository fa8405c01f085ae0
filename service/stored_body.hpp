#pragma once
// Response bodies read from the store part by part while they are sent: a response holds one
// part of at most kStoredPart stored bytes (and, decompressing, one buffer of as many output
// bytes and zlib's state), not the whole body. 100 clients that asked for a 9.9 MB VTU and did
// not read held about 28 MB each before (issue 50, item 7).
//
// The VTU: a client that takes gzip gets the stored bytes as they are (Content-Encoding: gzip;
// the store compresses at level 1, as the response did); any other client gets them
// decompressed on the way, its Content-Length from the gzip trailer. The result JSON: as
// stored. Never cpp-httplib's own compression: with brotli built in, cpp-httplib 0.11.4
// answers a browser (Accept-Encoding: br) at brotli quality 11, which took 51 s for an 18.7 MB
// VTU (docs/service.md, "Storage"); a content provider of known length is written as it is.
// Byte ranges are served from any offset.

#include <httplib.h>

#include <cstdint>

#include "job_store.hpp"

namespace fosls::service {

/// Stored bytes read per part (and decompressed bytes written per part).
constexpr std::int64_t kStoredPart = 256 * 1024;

/// Makes the job's VTU, stored as `stored`, the body of `res` with `content_type`. The store
/// must outlive the response; a job deleted while its VTU is sent ends the connection early.
void set_stored_vtu_body(const httplib::Request& req, httplib::Response& res, JobStore& store,
                         std::int64_t id, const StoredVtu& stored, const std::string& content_type);

/// Makes the job's result JSON, `bytes` long as stored, the body of `res`; as the VTU's.
void set_stored_result_body(httplib::Response& res, JobStore& store, std::int64_t id,
                            std::int64_t bytes);

}  // namespace fosls::service
