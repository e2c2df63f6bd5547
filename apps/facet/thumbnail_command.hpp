// `facet thumbnail -s SIZE INPUT OUTPUT`: a square PNG of a model, SIZE pixels a side, in the
// shape desktop thumbnailers call (data/facet.thumbnailer: file managers run it with %s %i %o).
// INPUT may be a file:// URI; OUTPUT is written as a PNG whatever its name, atomically, and
// nothing is written if the model cannot be drawn.
#pragma once

#include <string>

#include "cli_fwd.hpp"

namespace facet::cli {

struct ThumbnailOptions {
  int size = 256;  // the longest edge; thumbnails are square
  std::string input;
  std::string output;
};

// Adds the `thumbnail` subcommand and its flags to app; options are filled on parse.
CLI::App* add_thumbnail_command(CLI::App& app, ThumbnailOptions& options);

// The local path a thumbnailer's INPUT names: a plain path as it is, a file:// URI (with or
// without the host `localhost`) decoded from its %XX escapes. Throws facet::Error for another
// scheme or host, or a bad escape.
std::string local_path(const std::string& input);

// Draws the model and writes the PNG; throws facet::Error on a bad value or file. Returns 0.
int run_thumbnail(const ThumbnailOptions& options);

}  // namespace facet::cli
