// The `facet render` options for frame sequences and output files (--time, --frames, --fps,
// --shard, --camera-path, --outputs, --normal-space, --overwrite, --quiet), and the job they
// describe once checked: which frames this run draws, at what times, into which files.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "camera_path.hpp"
#include "cli_fwd.hpp"
#include "frame_sequence.hpp"
#include "output_files.hpp"

namespace facet::cli {

struct FrameOptions {
  std::optional<double> time;         // one frame at this time
  std::optional<std::string> frames;  // "A:B"
  double fps = 30.0;
  std::optional<std::string> shard;  // "I/N"
  std::string camera_path;           // empty: the camera stands still
  std::string outputs = "color";
  std::string normal_space = "world";
  bool overwrite = false;
  bool quiet = false;
};

// Adds the options to the render subcommand.
void add_frame_options(CLI::App& command, FrameOptions& options);

struct Frame {
  int number = 0;        // fills the output name's %d
  double seconds = 0.0;  // on the animation clock: --time, or number / fps
};

struct FrameJob {
  bool sequence = false;      // --frames: skips frames already written, reports progress
  std::vector<Frame> frames;  // what this run (this shard) renders, in order
  FramePattern pattern{""};
  OutputPlan outputs;
  std::optional<CameraPath> camera_path;
  bool overwrite = false;
  bool quiet = false;
  std::string description;  // of a sequence: "frames 0:48 at 30 fps, shard 1/4: 12 frames"
};

// Checks every option and the output folder before anything is drawn. Throws facet::Error
// naming the flag (or the path) at fault.
FrameJob plan_frames(const FrameOptions& options, const std::string& output);

}  // namespace facet::cli
