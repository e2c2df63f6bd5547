#include "model_import.hpp"

#include <cmath>
#include <iostream>

#include "facet/error.hpp"
#include "facet/import.hpp"

namespace facet::cli {
namespace {

// Puts a stream's buffer back however the import ends.
class SilencedStream {
 public:
  explicit SilencedStream(std::ostream& stream) : stream_(stream), buffer_(stream.rdbuf(nullptr)) {}
  ~SilencedStream() {
    stream_.rdbuf(buffer_);
    stream_.clear();  // writes to a stream without a buffer set badbit
  }
  SilencedStream(const SilencedStream&) = delete;
  SilencedStream& operator=(const SilencedStream&) = delete;

 private:
  std::ostream& stream_;
  std::streambuf* buffer_;
};

}  // namespace

Scene import_model(const std::string& path, bool allow_outside_paths, double timeout_seconds) {
  ImportOptions options;
  options.allow_outside_paths = allow_outside_paths;
  options.import_time_limit_seconds = timeout_seconds;
  return import_model(path, options);
}

Scene import_model(const std::string& path, const ImportOptions& options) {
  const double timeout_seconds = options.import_time_limit_seconds;
  if (!(timeout_seconds >= 0.0) || std::isinf(timeout_seconds))
    throw Error("--import-timeout: must be a number of seconds >= 0 (0: no limit)");
  SilencedStream out(std::cout), err(std::cerr);
  return import_scene(path, options);
}

}  // namespace facet::cli
