// `facet thumbnail` (see thumbnail_command.hpp).
#include "thumbnail_command.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "facet/error.hpp"
#include "render_command.hpp"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kLargestSize = 4096;  // freedesktop's largest thumbnails are 1024; room above

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

bool ends_with_png(const std::string& path) {
  if (path.size() < 4) return false;
  std::string tail = path.substr(path.size() - 4);
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".png";
}

}  // namespace

CLI::App* add_thumbnail_command(CLI::App& app, ThumbnailOptions& o) {
  CLI::App* cmd = app.add_subcommand("thumbnail",
                                     "Write a square PNG thumbnail of a model on a transparent "
                                     "background (for desktop thumbnailers)");
  cmd->add_option("-s,--size", o.size, "Edge of the square image in pixels, 1 .. 4096")
      ->capture_default_str();
  cmd->add_option("INPUT", o.input, "Model file, or a file:// URI")->required();
  cmd->add_option("OUTPUT", o.output, "PNG file to write (a PNG whatever its name)")->required();
  return cmd;
}

std::string local_path(const std::string& input) {
  const std::string scheme = "file://";
  if (input.compare(0, scheme.size(), scheme) != 0) {
    std::size_t colon = input.find("://");
    if (colon != std::string::npos && input.find('/') > colon) {
      throw Error(input + ": only local files (file:// URIs) can be read");
    }
    return input;
  }
  std::string rest = input.substr(scheme.size());
  std::size_t slash = rest.find('/');
  std::string host = rest.substr(0, slash);
  if (slash == std::string::npos || (!host.empty() && host != "localhost")) {
    throw Error(input + ": only local files (file:///PATH) can be read");
  }
  std::string path;
  for (std::size_t i = slash; i < rest.size(); ++i) {
    if (rest[i] != '%') {
      path += rest[i];
      continue;
    }
    int high = i + 2 < rest.size() ? hex_digit(rest[i + 1]) : -1;
    int low = i + 2 < rest.size() ? hex_digit(rest[i + 2]) : -1;
    if (high < 0 || low < 0 || (high == 0 && low == 0)) {
      throw Error(input + ": a bad %XX escape in the URI");
    }
    path += static_cast<char>(high * 16 + low);
    i += 2;
  }
  return path;
}

int run_thumbnail(const ThumbnailOptions& t) {
  if (t.size < 1 || t.size > kLargestSize) {
    throw Error("--size: expected 1 .. " + std::to_string(kLargestSize) + " pixels, got " +
                std::to_string(t.size));
  }
  RenderOptions o;
  o.scene.model = local_path(t.input);
  o.size = std::to_string(t.size) + "x" + std::to_string(t.size);
  o.background = "none";  // a file manager shows the thumbnail on its own background
  o.frames.quiet = true;
  if (ends_with_png(t.output)) {
    o.output = t.output;
    return run_render(o);
  }
  // Thumbnailers may name the output without .png: draw to a hidden .png beside it (written
  // whole, then renamed, like every output) and rename that into place.
  fs::path target(t.output);
  fs::path temporary = target.parent_path() / ("." + target.filename().string() + ".facet-" +
                                               std::to_string(::getpid()) + ".png");
  o.output = temporary.string();
  run_render(o);
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec) {
    std::string reason = ec.message();
    fs::remove(temporary, ec);
    throw Error(t.output + ": cannot write (" + reason + ")");
  }
  return 0;
}

}  // namespace facet::cli
