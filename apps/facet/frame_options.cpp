// Frame and output options of `facet render` (see frame_options.hpp).
#include "frame_options.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>

#include "arguments.hpp"
#include "facet/error.hpp"

namespace facet::cli {
namespace {

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

void add_frame_options(CLI::App& cmd, FrameOptions& o) {
  cmd.add_option("--time", o.time,
                 "Animation time in seconds of the one frame drawn: poses the islands and "
                 "--camera-path (default: 0)");
  cmd.add_option("--frames", o.frames,
                 "Render frames A to B-1 (B exclusive) into -o NAME_%04d.png, frame N at time "
                 "N / FPS; frames whose files all exist are skipped");
  cmd.add_option("--fps", o.fps, "Frames per second of --frames")->capture_default_str();
  cmd.add_option("--shard", o.shard,
                 "Render only frames A+I, A+I+N, ... of --frames A:B, I from 0 to N-1 (a Slurm "
                 "array task: $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)");
  cmd.add_option("--camera-path", o.camera_path,
                 "Fly along the timed camera keys in FILE (lines of: t x y z yaw pitch)");
  cmd.add_option("--outputs", o.outputs,
                 "Images to write, comma-separated: " + joined(output_names()) +
                     ". With -o out.png, color goes to out.png, the others to out.NAME.exr (ids: "
                     "out.NAME.png, 16-bit); with out.exr or out.npy every output is in that "
                     "format; out.npz holds one array per output")
      ->capture_default_str();
  cmd.add_option("--normal-space", o.normal_space, "Space of the normal output: world or camera")
      ->capture_default_str();
  cmd.add_flag("--overwrite", o.overwrite,
               "With --frames, render frames whose files exist too (default: skip them)");
  cmd.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
}

FrameJob plan_frames(const FrameOptions& o, const std::string& output) {
  FrameJob job;
  if (o.time && !std::isfinite(*o.time)) throw Error("--time: must be a finite number of seconds");
  if (!(std::isfinite(o.fps) && o.fps > 0.0)) {
    throw Error("--fps: must be a positive number of frames per second, got " + number_text(o.fps));
  }
  job.pattern = FramePattern(output);
  job.outputs = plan_outputs(o.outputs, o.normal_space, output);
  job.overwrite = o.overwrite;
  job.quiet = o.quiet;

  int first_frame = 0;
  if (o.frames) {
    if (o.time) {
      throw Error(
          "--time: --frames gives each frame its own time (frame / fps); use one or the "
          "other");
    }
    FrameRange range = parse_frames(*o.frames);
    first_frame = range.first;
    Shard shard = o.shard ? parse_shard(*o.shard) : Shard{};
    if (range.count() > 1 && !job.pattern.numbered()) {
      throw Error("--output: '" + output + "' has no %d for the frame number, and --frames " +
                  *o.frames + " is " + std::to_string(range.count()) +
                  " frames (name them like frame_%04d.png)");
    }
    job.sequence = true;
    for (int number : shard_frames(range, shard)) job.frames.push_back({number, number / o.fps});
    job.description = "frames " + *o.frames + " at " + number_text(o.fps) + " fps";
    if (o.shard) {
      job.description += ", shard " + *o.shard + ": " + std::to_string(job.frames.size()) + " of " +
                         std::to_string(range.count()) + " frames";
    }
  } else {
    if (o.shard) throw Error("--shard: shares out the frames of --frames A:B; give that too");
    if (job.pattern.numbered()) {
      throw Error("--output: '" + output + "' has a frame number (%d) but there is no --frames " +
                  "A:B to fill it in");
    }
    job.frames.push_back({0, o.time.value_or(0.0)});
  }
  if (!o.camera_path.empty()) job.camera_path = CameraPath::load(o.camera_path);

  // Every frame's files share one folder (the number is only in the name): the range's first
  // frame stands for all, also for a shard left with none. An existing file is replaced only by
  // a single frame or --overwrite; a sequence skips it.
  bool replacing = !job.sequence || job.overwrite;
  for (const std::string& file : job.outputs.files(job.pattern.path(first_frame))) {
    check_output_path(file, replacing);
  }
  return job;
}

}  // namespace facet::cli
