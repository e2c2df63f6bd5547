// Rendering a job's frames (see render_frames.hpp).
#include "render_frames.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "facet/color.hpp"
#include "facet/scene.hpp"
#include "progress.hpp"
#include "stop_signals.hpp"

namespace facet::cli {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A frame is complete when all its files exist: each is renamed into place only when whole.
bool all_exist(const std::vector<std::string>& files) {
  std::error_code ec;
  for (const std::string& file : files) {
    if (!std::filesystem::exists(file, ec)) return false;
  }
  return true;
}

// Color drawn over a transparent background is premultiplied (blending over alpha 0 scales it
// by coverage); 8-bit images (PNG) carry straight alpha, so partly covered pixels are divided
// by their alpha, in linear light. Float color (OpenEXR) stays premultiplied, EXR's convention.
void straighten_alpha(Framebuffer& framebuffer) {
  if (framebuffer.format() != ColorFormat::rgba8_srgb) return;
  std::vector<std::uint8_t>& rgba = framebuffer.rgba8();
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    const int alpha = rgba[i + 3];
    if (alpha == 0 || alpha == 255) continue;
    glm::vec3 srgb(rgba[i], rgba[i + 1], rgba[i + 2]);
    glm::vec3 linear = srgb_to_linear(srgb / 255.0f) * (255.0f / static_cast<float>(alpha));
    glm::vec3 straight = linear_to_srgb(glm::min(linear, glm::vec3(1.0f))) * 255.0f + 0.5f;
    for (int c = 0; c < 3; ++c) rgba[i + c] = static_cast<std::uint8_t>(straight[c]);
  }
}

}  // namespace

FrameRenderer::FrameRenderer(Renderer& renderer, AnimatedScene& scene, const Camera& camera,
                             const FrameJob& job, ImageSize size, GlBackend* gl)
    : renderer_(renderer),
      scene_(scene),
      camera_(camera),
      job_(job),
      framebuffer_(size.width, size.height, job.outputs.color_format(), DepthImage::none,
                   job.outputs.extra_outputs()),
      gl_(gl) {
  check_ids_fit(job.outputs, scene.scene());
}

const Framebuffer& FrameRenderer::render(double seconds) {
  Scene& scene = scene_.at(seconds);
  Camera camera = camera_;
  if (job_.camera_path) {
    // The path moves the eye and turns the view; the lens (field of view, clip planes) stays.
    FirstPersonCamera pose = job_.camera_path->at(seconds);
    camera.eye = pose.position;
    camera.target = pose.position + pose.forward();
    camera.up = {0.0f, 1.0f, 0.0f};
  }
  if (gl_ != nullptr) {
    gl_->render(scene, camera, framebuffer_);
  } else {
    renderer_.begin_frame(camera, scene.lighting);
    draw_scene(renderer_, scene);
    renderer_.finish(framebuffer_);
  }
  if (renderer_.settings().clear_color.a < 1.0f) straighten_alpha(framebuffer_);
  return framebuffer_;
}

int render_sequence(const FrameJob& job, FrameRenderer& frames, ImageSize size) {
  const int total = static_cast<int>(job.frames.size());
  Progress progress(Progress::style_for(stdout, job.quiet), total);
  progress.start(job.pattern.text() + ": " + std::to_string(size.width) + "x" +
                 std::to_string(size.height) + ", " + job.description);
  StopSignals stop;
  try {
    for (const Frame& frame : job.frames) {
      std::string path = job.pattern.path(frame.number);
      std::vector<std::string> files = job.outputs.files(path);
      if (!job.overwrite && all_exist(files)) {
        progress.skipped(frame.number);
      } else {
        auto start = Clock::now();
        const Framebuffer& image = frames.render(frame.seconds);
        double render_ms = ms_since(start);
        auto rendered = Clock::now();
        write_outputs(image, job.outputs, path);
        progress.rendered(frame.number, files, render_ms, ms_since(rendered));
      }
      if (int signal = stop.received(); signal != 0 && progress.done() < total) {
        progress.end_line();
        std::fprintf(stderr,
                     "facet: stopped by %s after %d of %d frames, each written whole; run the "
                     "same command again to render the rest\n",
                     signal == SIGINT ? "Ctrl-C (SIGINT)" : "SIGTERM", progress.done(), total);
        return 128 + signal;
      }
    }
  } catch (...) {
    progress.end_line();
    throw;
  }
  progress.finish();
  return 0;
}

}  // namespace facet::cli
