// The GL twin's frame, top to bottom (GlRenderer::render, on the renderer's GL thread): the draws
// in facet's order, the opaque ones, the sky where nothing opaque was drawn, the blended ones back
// to front, then the readback (or, timed as glmark2 times a frame, GlRenderer::draw: glFinish).
// Each draw picks a program for its shading model (glsl_fragment.cpp), as facet's renderer picks a
// specialised raster loop (pipeline/record/pipeline_table.cpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/gl.hpp"
#include "gl/draw_list.hpp"
#include "gl/draw_uniforms.hpp"
#include "gl/egl_context.hpp"
#include "gl/frame_target.hpp"
#include "gl/gl_program.hpp"
#include "gl/gl_thread.hpp"
#include "gl/glsl_sources.hpp"
#include "gl/gpu_resources.hpp"

namespace facet {
namespace {

using gl::GlDraw;
using gl::Program;

bool is_blended(AlphaMode mode) { return mode == AlphaMode::blend || mode == AlphaMode::additive; }

// The GLSL define of a shading model. Wireframe draws only edges, in the wire color.
const char* model_define(ShadingModel model) {
  switch (model) {
    case ShadingModel::unlit:
      return "MODEL_UNLIT";
    case ShadingModel::vertex_color:
      return "MODEL_VERTEX_COLOR";
    case ShadingModel::flat:
      return "MODEL_FLAT";
    case ShadingModel::gouraud:
      return "MODEL_GOURAUD";
    case ShadingModel::phong:
      return "MODEL_PHONG";
    case ShadingModel::blinn_phong:
      return "MODEL_BLINN_PHONG";
    case ShadingModel::pbr:
      return "MODEL_PBR";
    case ShadingModel::depth:
      return "MODEL_DEPTH";
    case ShadingModel::normals:
      return "MODEL_NORMALS";
    case ShadingModel::texcoords:
      return "MODEL_TEXCOORDS";
    case ShadingModel::wireframe:
      return "MODEL_WIRE";
    default:  // lambert, and wire_overlay's fill
      return "MODEL_LAMBERT";
  }
}

// Debug views show data and the wireframe shows edges: always opaque, as facet's pipeline
// table has them (pipeline/record/pipeline_table.cpp).
bool always_opaque(ShadingModel m) {
  return m == ShadingModel::depth || m == ShadingModel::normals || m == ShadingModel::texcoords ||
         m == ShadingModel::wireframe;
}

// The tone mapping of a frame: none when every draw shows data (the depth, normals and
// texture-coordinate views), as facet's resolve leaves frames of display values alone.
ToneMapping tone_mapping_of(const std::vector<GlDraw>& draws, const RenderSettings& settings) {
  const bool data_only =
      !draws.empty() && std::all_of(draws.begin(), draws.end(), [](const GlDraw& draw) {
        const ShadingModel m = draw.material->shading;
        return m == ShadingModel::depth || m == ShadingModel::normals ||
               m == ShadingModel::texcoords;
      });
  return data_only ? ToneMapping::none : settings.tone_mapping;
}

// Blending as facet's raster loop writes a pixel (pixel_writer.hpp's blend_into): "over" with
// straight alpha, or color x alpha added. Blended draws test depth but do not write it.
void set_blending(AlphaMode mode) {
  if (mode == AlphaMode::blend) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
  } else if (mode == AlphaMode::additive) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_ZERO, GL_ONE);
    glDepthMask(GL_FALSE);
  } else {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
}

// Face culling; front faces are counter-clockwise, in facet as in OpenGL.
void set_culling(CullMode cull) {
  if (cull == CullMode::none) {
    glDisable(GL_CULL_FACE);
    return;
  }
  glEnable(GL_CULL_FACE);
  glCullFace(cull == CullMode::back ? GL_BACK : GL_FRONT);
}

}  // namespace

// Everything that needs the context current: it lives and is used on the GL thread only.
struct GlState {
  RenderSettings settings;
  gl::EglContext context;  // first: everything below needs it current
  std::string renderer_name, version;
  gl::GpuResources resources;
  gl::FrameTarget target;
  std::map<std::string, std::unique_ptr<Program>> programs;
  GLuint empty_vertex_array = 0;  // the sky's triangle has no attributes, but core GL wants one
  double last_ms = 0.0;
  std::uint64_t frames = 0;

  explicit GlState(const RenderSettings& s) : settings(s) {
    auto gl_string = [](GLenum name) {
      const GLubyte* text = glGetString(name);
      return text ? std::string(reinterpret_cast<const char*>(text)) : std::string("unknown");
    };
    renderer_name = gl_string(GL_RENDERER);
    version = gl_string(GL_VERSION);
    glGenVertexArrays(1, &empty_vertex_array);
  }
  ~GlState() { glDeleteVertexArrays(1, &empty_vertex_array); }

  // A draw's program (`geometry_stage`: with the geometry stage), or the sky's.
  Program& program(const std::string& defines, bool geometry_stage, bool sky = false) {
    auto& slot = programs[(sky ? "sky " : "") + defines];
    if (!slot) {
      const std::string common = gl::kCommonGlsl;
      slot = sky ? std::make_unique<Program>(defines, common + gl::kSkyVertexGlsl, "",
                                             common + gl::kSkyFragmentGlsl)
                 : std::make_unique<Program>(
                       defines, common + gl::kVertexGlsl,
                       geometry_stage ? common + gl::kGeometryGlsl : std::string(),
                       common + gl::kFragmentGlsl);
    }
    return *slot;
  }

  // Whether a draw reads what the geometry stage makes per triangle (glsl_stages.cpp): face
  // normals where the mesh has none, flat shading's color, the wire overlay's edges, and which
  // side the normals face for two-sided lighting; lines and points pass through it. Without it,
  // llvmpipe skips a stage it pays for per triangle, and the image is the same.
  static bool needs_geometry_stage(const gl::GpuMesh& mesh, const Material& material,
                                   const char* model) {
    return mesh.mode != GL_TRIANGLES || !mesh.has_normals || material.cull == CullMode::none ||
           material.shading == ShadingModel::wire_overlay || std::strcmp(model, "MODEL_FLAT") == 0;
  }

  // Draws the mesh with the program of `model` (a MODEL_* define of glsl_fragment.cpp).
  void draw_pass(const GlDraw& draw, const Material& material, const char* model,
                 const gl::FrameState& frame) {
    const gl::GpuMesh& mesh = resources.mesh(*draw.mesh);
    std::string defines = std::string("#define ") + model + "\n";
    if (material.shading == ShadingModel::wire_overlay) defines += "#define WIRE_OVERLAY\n";
    if (material.alpha_mode == AlphaMode::opaque || material.alpha_mode == AlphaMode::mask) {
      defines += "#define ALPHA_OPAQUE\n";  // alpha 1 where drawn, as facet writes
    }
    if (material.alpha_mode == AlphaMode::mask) {
      defines += "#define ALPHA_MASK\n";
      if (target.samples() > 1) {  // gl_SampleMask: GLSL 4.00, or 3.30 with this extension
        defines += "#extension GL_ARB_sample_shading : enable\n#define ALPHA_TO_COVERAGE " +
                   std::to_string(target.samples()) + "\n";
      }
    }
    if (mesh.mode == GL_LINES) defines += "#define PRIMITIVE_LINES\n";
    if (mesh.mode == GL_POINTS) defines += "#define PRIMITIVE_POINTS\n";
    const bool geometry_stage = needs_geometry_stage(mesh, material, model);
    if (!geometry_stage) defines += "#define NO_GEOMETRY_STAGE\n";
    Program& p = program(defines, geometry_stage);
    glUseProgram(p.id());
    gl::set_frame_uniforms(p, frame);
    gl::set_draw_uniforms(p, draw, material, frame, mesh.has_normals, resources);
    mesh.bind();
    mesh.draw();
  }

  void draw(const GlDraw& draw, const gl::FrameState& frame) {
    Material material = *draw.material;
    const Mesh& mesh = **draw.mesh;
    if (always_opaque(material.shading)) material.alpha_mode = AlphaMode::opaque;
    set_culling(material.cull);
    set_blending(material.alpha_mode);
    // Points and lines are unlit (facet colors them at setup: vertex color x base color).
    if (mesh.topology == Topology::points || mesh.topology == Topology::lines) {
      material.base_color_map = {};
      draw_pass(draw, material, "MODEL_UNLIT", frame);
      return;
    }
    if (material.shading == ShadingModel::vertex_color) {
      material.base_color = glm::vec4(1.0f), material.use_vertex_colors = true;
    }
    if (material.shading == ShadingModel::wireframe) {  // the edges alone, as GL lines
      glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
      draw_pass(draw, material, "MODEL_WIRE", frame);
      glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
      return;
    }
    draw_pass(draw, material, model_define(material.shading), frame);
  }

  // The environment image, which reflections and the sky read, on its own texture unit for the
  // whole frame.
  void bind_environment(const Environment& env) {
    if (!env.image) return;
    Sampler sampler;  // environment.cpp: trilinear, v clamped; a sphere map clamps u too
    sampler.wrap_v = Wrap::clamp_to_edge;
    if (env.projection == EnvironmentProjection::sphere_map) sampler.wrap_u = Wrap::clamp_to_edge;
    glActiveTexture(GL_TEXTURE0 + gl::kEnvironmentUnit);
    glBindTexture(GL_TEXTURE_2D, resources.texture(env.image));
    glBindSampler(gl::kEnvironmentUnit, resources.sampler(sampler));
  }

  void draw_sky(const gl::FrameState& frame) {
    Program& p = program("", false, true);
    glUseProgram(p.id());
    gl::set_frame_uniforms(p, frame);
    set_blending(AlphaMode::opaque);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);  // only where the depth is still the clear depth, 1
    glDisable(GL_CULL_FACE);
    glBindVertexArray(empty_vertex_array);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthFunc(GL_LESS);
  }

  void render(const Scene& scene, const Camera& camera, Framebuffer& out) {
    const auto start = std::chrono::steady_clock::now();
    const ToneMapping tone_mapping =
        draw_frame(scene, camera, out, gl::FrameTarget::Color::linear_float);
    target.read(out,
                {settings.exposure, tone_mapping, scene.lighting.environment.show_as_background});
    resources.free_unused();
    last_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }

  void draw_only(const Scene& scene, const Camera& camera, Framebuffer& out, bool read) {
    if (out.format() != ColorFormat::rgba8_srgb) {
      throw Error("OpenGL backend: a frame timed as glmark2 times one draws into 8-bit sRGB");
    }
    const auto start = std::chrono::steady_clock::now();
    draw_frame(scene, camera, out, gl::FrameTarget::Color::srgb8);
    target.finish();
    last_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (read) target.read_codes(out);
    resources.free_unused();
  }

  // Every draw of the frame into the target bound with that color buffer; returns the frame's
  // tone mapping, which the readback applies.
  ToneMapping draw_frame(const Scene& scene, const Camera& camera, const Framebuffer& out,
                         gl::FrameTarget::Color color) {
    if (out.extra_outputs().any()) {
      throw Error(
          "OpenGL backend: extra outputs (depth in scene units, normals, ids, ...) are "
          "drawn by facet's own renderer only");
    }
    if (!out.has_color())
      throw Error("OpenGL backend: a depth-only framebuffer has no color image");
    context.make_current();
    camera.validate();
    gl::FrameState frame;
    frame.number = ++frames;
    resources.begin_frame(frame.number);
    frame.lighting = &scene.lighting;
    frame.eye = camera.shading_eye();
    frame.view_projection = camera.view_projection();
    if (camera.projection_kind == Projection::orthographic) {
      frame.view_depth = {0.0f, camera.far_plane - camera.near_plane, camera.near_plane};
    }
    frame.display_exact = out.format() == ColorFormat::rgba32f;
    frame.viewport = {out.width(), out.height()};
    const std::vector<GlDraw> draws = gl::ordered_draws(scene, camera);
    const ToneMapping tone_mapping = tone_mapping_of(draws, settings);
    frame.fog_color =
        fog_color_under(tone_mapping, scene.lighting.fog.color, std::exp2(settings.exposure));
    gl::depth_view_range(draws, camera, frame.depth_view_near, frame.depth_view_far);

    bind_environment(scene.lighting.environment);
    target.bind(out.width(), out.height(), settings.msaa, color);
    // The last frame may have left depth writes off (blended draws, the sky), and glClear
    // obeys the depth mask.
    set_blending(AlphaMode::opaque);
    const glm::vec4 clear = settings.clear_color;
    glClearColor(clear.r, clear.g, clear.b, clear.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_PROGRAM_POINT_SIZE);

    bool sky_pending = scene.lighting.environment.show_as_background;
    for (const GlDraw& draw : draws) {
      if (sky_pending && is_blended(draw.material->alpha_mode)) {
        draw_sky(frame), sky_pending = false;
      }
      this->draw(draw, frame);
    }
    if (sky_pending) draw_sky(frame);
    return tone_mapping;
  }
};

struct GlRenderer::Impl {
  gl::GlThread thread;
  std::unique_ptr<GlState> state;  // made, used and destroyed on the thread
};

GlRenderer::GlRenderer(const RenderSettings& settings) : impl_(std::make_unique<Impl>()) {
  impl_->state = impl_->thread.run([&] { return std::make_unique<GlState>(settings); });
}
GlRenderer::~GlRenderer() {
  impl_->thread.run([this] { impl_->state.reset(); });
}
const std::string& GlRenderer::renderer_name() const { return impl_->state->renderer_name; }
const std::string& GlRenderer::version() const { return impl_->state->version; }
double GlRenderer::last_frame_ms() const { return impl_->state->last_ms; }
void GlRenderer::render(const Scene& scene, const Camera& camera, Framebuffer& target) {
  impl_->thread.run([&] { impl_->state->render(scene, camera, target); });
}
void GlRenderer::draw(const Scene& scene, const Camera& camera, Framebuffer& target, bool read) {
  impl_->thread.run([&] { impl_->state->draw_only(scene, camera, target, read); });
}

}  // namespace facet
