// `facet render` on several models or folders at once (a batch): one image per model into an
// output folder, named after the model, a bad file reported and skipped, a progress bar on a
// terminal and a summary at the end. Each model is drawn by run_render with the same options,
// so a batch draws exactly what the single-model command would.
#pragma once

#include <string>
#include <vector>

#include "cli_fwd.hpp"

namespace facet::cli {

struct RenderOptions;

struct BatchOptions {
  std::vector<std::string> models;  // positional MODEL...: files and folders
  std::string format = "png";       // the extension of a batch's images
};

// Adds the batch's own flag (--format) to the render subcommand.
void add_batch_options(CLI::App& command, BatchOptions& options);

// True when the command line asks for a batch: more than one model, a folder among them, or a
// model and an output that names a folder (ends with '/').
bool is_batch(const BatchOptions& options, const std::string& output);

// One model of a batch and the image it is written to.
struct BatchItem {
  std::string model;
  std::string output;
};

// The models a batch draws, in order: the files named, in the order given, and the files with a
// model extension (model_extensions()) found in each folder named, recursively, sorted by path.
// Each image is OUTPUT_FOLDER/SUBFOLDERS/STEM.EXTENSION, where SUBFOLDERS is the model's folder
// relative to the folder named (empty for a file named directly). A name already taken by an
// earlier model gets -2, -3, ... before its extension, so the names depend only on the
// command line and the folders' contents. Throws facet::Error if no model is found.
std::vector<BatchItem> plan_batch(const std::vector<std::string>& models,
                                  const std::string& output_folder, const std::string& extension);

// The extensions (lower case, with the dot) a folder's files must have to be drawn.
const std::vector<std::string>& model_extensions();

// Runs the batch. Returns 0 if every model was written, 1 if some failed (each named on stderr),
// 128 + the signal after a Ctrl-C or SIGTERM; throws facet::Error for a bad option, before any
// model is drawn.
int run_batch(const RenderOptions& options);

// What `facet render` runs: run_batch for a batch, else run_render on the one model.
int run_render_command(const RenderOptions& options);

}  // namespace facet::cli
