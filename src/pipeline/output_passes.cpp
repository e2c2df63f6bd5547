// The extra outputs (facet/framebuffer.hpp's ExtraOutputs): after the color pass, the frame's
// draws run again once per group of outputs asked for, each with a shading model that writes
// data (shading/output_models.hpp) into a float target, whose channels are then copied to the
// framebuffer's images. Only what is asked for runs.
#include <algorithm>
#include <string>

#include "facet/error.hpp"
#include "pipeline/record/output_pipelines.hpp"
#include "pipeline/renderer_impl.hpp"
#include "shading/output_models.hpp"

namespace facet {

using pipeline::OutputPass;

namespace {

// Copies channel `channel` of a pass's four floats a pixel into `out`, converted to T (ids from
// their exact floats); nothing when the output was not asked for (`out` empty).
template <class T>
void copy_channel(const std::vector<float>& rgba, int channel, std::vector<T>& out) {
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<T>(rgba[4 * i + channel]);
}

// Copies a pass's four floats a pixel into the images of the extra outputs it holds.
void copy_pass(OutputPass pass, const std::vector<float>& rgba, Framebuffer& target) {
  const std::size_t pixels = rgba.size() / 4;
  switch (pass) {
    case OutputPass::depth_and_instance:
      copy_channel(rgba, 0, target.view_depth());
      copy_channel(rgba, 1, target.ray_distance());
      copy_channel(rgba, 2, target.instance_ids());
      break;
    case OutputPass::normals:
      for (std::size_t i = 0; i < pixels; ++i) {
        std::copy_n(&rgba[4 * i], 3, &target.normals()[3 * i]);
      }
      break;
    case OutputPass::triangles:
      copy_channel(rgba, 0, target.triangle_ids());
      if (!target.barycentrics().empty()) {
        float* b = target.barycentrics().data();
        for (std::size_t i = 0; i < pixels; ++i, b += 3) {
          const float* p = &rgba[4 * i];
          b[0] = p[0] == 0.0f ? 0.0f : 1.0f - p[1] - p[2], b[1] = p[1], b[2] = p[2];
        }
      }
      break;
    case OutputPass::albedo:
      target.albedo().assign(rgba.begin(), rgba.end());
      break;
  }
}

}  // namespace

void Renderer::Impl::check_extra_outputs(const Framebuffer& target) const {
  const ExtraOutputs& want = target.extra_outputs();
  for (const pipeline::DrawRecord& draw : frame.draws) {
    if ((want.triangle_ids || want.barycentrics) &&
        draw.mesh->primitive_count() >= shading::kMaxExactId) {
      throw Error("renderer: triangle ids of a mesh of " +
                  std::to_string(draw.mesh->primitive_count()) + " triangles: at most " +
                  std::to_string(shading::kMaxExactId - 1) + " a mesh");
    }
    if (want.instance_ids && draw.uniforms.instance_id >= shading::kMaxExactId) {
      throw Error("renderer: instance id " + std::to_string(draw.uniforms.instance_id) +
                  " is above the largest the instance ids output holds, " +
                  std::to_string(shading::kMaxExactId - 1));
    }
  }
}

void Renderer::Impl::run_extra_outputs(Framebuffer& target) {
  const auto start = pipeline::Clock::now();
  const ExtraOutputs& want = target.extra_outputs();
  // What the passes change, put back afterwards: the frame's stats are the color pass's.
  const FrameStats color_stats = frame.stats;
  const RenderSettings color_settings = settings;
  const Lighting color_lighting = lighting;
  settings.exposure = 0.0f;
  settings.tone_mapping = ToneMapping::none;
  settings.debug_view = DebugView::none;
  settings.clear_color = glm::vec4(0.0f);
  // Ids, normals and depths are not averaged: each pixel takes its centre's winner.
  settings.msaa = 1;
  lighting.fog.mode = FogMode::none;
  lighting.environment.show_as_background = false;
  // Lines and points are color only: the passes leave their pixels empty (no depth, id or
  // normal), as they do the background. Blended draws are drawn opaque (the draws are not needed
  // again: the next frame records its own).
  std::erase_if(frame.draws, [](const pipeline::DrawRecord& d) {
    return d.mesh->topology == Topology::lines || d.mesh->topology == Topology::points ||
           !d.pipeline.fills_triangles;
  });
  for (pipeline::DrawRecord& draw : frame.draws) {
    if (draw.material.alpha_mode != AlphaMode::mask) draw.material.alpha_mode = AlphaMode::opaque;
  }
  if (!pass_target || pass_target->width() != target.width() ||
      pass_target->height() != target.height()) {
    pass_target.emplace(target.width(), target.height(), ColorFormat::rgba32f, DepthImage::none);
  }
  const auto run_pass = [&](OutputPass pass) {
    for (pipeline::DrawRecord& draw : frame.draws) {
      draw.pipeline = pipeline::output_pipeline(pass, want.normals, draw.material.alpha_mode);
    }
    run(*pass_target);
    copy_pass(pass, pass_target->rgba32f(), target);
  };
  if (want.view_depth || want.ray_distance || want.instance_ids) {
    run_pass(OutputPass::depth_and_instance);
  }
  if (want.normals != NormalSpace::none) run_pass(OutputPass::normals);
  if (want.triangle_ids || want.barycentrics) run_pass(OutputPass::triangles);
  if (want.albedo) run_pass(OutputPass::albedo);
  settings = color_settings;
  lighting = color_lighting;
  frame.stats = color_stats;
  frame.stats.ms_extra_outputs = pipeline::ms_since(start);
  frame.stats.ms_total += frame.stats.ms_extra_outputs;
}

}  // namespace facet
