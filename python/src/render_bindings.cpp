// facet.Renderer and facet.write_png: frames of a scene as NumPy arrays. render() checks its
// arguments, renders with the GIL released (so renderers in several Python threads work at
// once), and hands each requested output over as an array that owns the framebuffer's buffer.
// Each output is one entry of kOutputs and one small function that takes it out of the frame.
// render_to() renders the same way into a facet.RenderTexture (render_texture_bindings.cpp).
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <variant>
#include <vector>

#include "array_conversion.hpp"
#include "bindings.hpp"
#include "camera_bindings.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/render_texture.hpp"
#include "facet/renderer.hpp"

namespace facet::python {
namespace {

// A rendered frame and the camera it was seen through.
struct RenderedFrame {
  Framebuffer image;
  Camera camera;
};

// One output's values and their shape, made without the GIL; an array of them with it.
struct OutputValues {
  std::variant<std::vector<std::uint8_t>, std::vector<float>, std::vector<std::uint32_t>> values;
  std::vector<py::ssize_t> shape;
};

// "color": H x W x 4, the framebuffer's own color: uint8 sRGB with linear alpha, or float32
// linear RGBA (color_format="float").
OutputValues take_color(RenderedFrame& frame) {
  std::vector<py::ssize_t> shape{frame.image.height(), frame.image.width(), 4};
  if (frame.image.format() == ColorFormat::rgba32f) {
    return {std::move(frame.image.rgba32f()), std::move(shape)};
  }
  return {std::move(frame.image.rgba8()), std::move(shape)};
}

// An extra output (facet::ExtraOutputs) moved out of the framebuffer: H x W, or H x W x
// `channels` when there are several.
template <class T>
OutputValues image_of(std::vector<T>& values, const Framebuffer& image, int channels) {
  std::vector<py::ssize_t> shape{image.height(), image.width()};
  if (channels > 1) shape.push_back(channels);
  return {std::move(values), std::move(shape)};
}

struct OutputKind {
  const char* name;
  void (*request)(ExtraOutputs& outputs, NormalSpace normals);
  OutputValues (*take)(RenderedFrame& frame);
};

// Each output as the framebuffer holds it (facet/framebuffer.hpp's ExtraOutputs says what the
// values are; 0 where nothing was drawn).
constexpr std::array<OutputKind, 8> kOutputs{{
    {"color", [](ExtraOutputs&, NormalSpace) {}, take_color},
    {"depth", [](ExtraOutputs& o, NormalSpace) { o.view_depth = true; },
     [](RenderedFrame& f) { return image_of(f.image.view_depth(), f.image, 1); }},
    {"distance", [](ExtraOutputs& o, NormalSpace) { o.ray_distance = true; },
     [](RenderedFrame& f) { return image_of(f.image.ray_distance(), f.image, 1); }},
    {"normal", [](ExtraOutputs& o, NormalSpace space) { o.normals = space; },
     [](RenderedFrame& f) { return image_of(f.image.normals(), f.image, 3); }},
    {"instance", [](ExtraOutputs& o, NormalSpace) { o.instance_ids = true; },
     [](RenderedFrame& f) { return image_of(f.image.instance_ids(), f.image, 1); }},
    {"triangle", [](ExtraOutputs& o, NormalSpace) { o.triangle_ids = true; },
     [](RenderedFrame& f) { return image_of(f.image.triangle_ids(), f.image, 1); }},
    {"barycentric", [](ExtraOutputs& o, NormalSpace) { o.barycentrics = true; },
     [](RenderedFrame& f) { return image_of(f.image.barycentrics(), f.image, 3); }},
    {"albedo", [](ExtraOutputs& o, NormalSpace) { o.albedo = true; },
     [](RenderedFrame& f) { return image_of(f.image.albedo(), f.image, 4); }},
}};

NormalSpace normal_space(const std::string& name) {
  if (name == "world") return NormalSpace::world;
  if (name == "camera") return NormalSpace::camera;
  throw Error("render: normal_space must be 'world' or 'camera', got '" + name + "'");
}

std::string output_names() {
  std::string names;
  for (const OutputKind& kind : kOutputs)
    names += (names.empty() ? "" : ", ") + std::string(kind.name);
  return names;
}

// The outputs asked for, each once, in the order asked; a single string is one name.
std::vector<const OutputKind*> requested_outputs(py::handle outputs) {
  std::vector<std::string> names;
  if (py::isinstance<py::str>(outputs)) {
    names.push_back(outputs.cast<std::string>());
  } else {
    try {
      for (py::handle name : py::iter(outputs)) names.push_back(py::str(name));
    } catch (const py::error_already_set&) {
      throw Error("render: outputs must be a sequence of names (" + output_names() + ")");
    }
  }
  std::vector<const OutputKind*> kinds;
  for (const std::string& name : names) {
    const OutputKind* kind = nullptr;
    for (const OutputKind& k : kOutputs) {
      if (name == k.name) kind = &k;
    }
    if (kind == nullptr) {
      throw Error("render: unknown output '" + name + "' (valid: " + output_names() + ")");
    }
    bool seen = false;
    for (const OutputKind* k : kinds) seen = seen || k == kind;
    if (!seen) kinds.push_back(kind);
  }
  return kinds;
}

ColorFormat color_format(const std::string& name) {
  if (name == "uint8") return ColorFormat::rgba8_srgb;
  if (name == "float") return ColorFormat::rgba32f;
  throw Error("render: color_format must be 'uint8' or 'float', got '" + name + "'");
}

ToneMapping tone_mapping_named(const std::string& name) {
  if (name == "none") return ToneMapping::none;
  if (name == "pbr-neutral") return ToneMapping::pbr_neutral;
  if (name == "aces") return ToneMapping::aces;
  throw Error("Renderer: tone_mapping must be 'none', 'pbr-neutral' or 'aces', got '" + name + "'");
}

// The locks a frame holds while it renders: its scene's, shared; those of the render textures
// the scene's materials sample, shared; and the render texture it renders into, if any,
// exclusive. Taken in one order, the scene first and then the render textures by address, so
// frames in several Python threads never wait for each other in a circle (a scene's lock is
// held exclusively only by changes to it, which take no other lock). Made with the GIL released.
class FrameLocks {
 public:
  FrameLocks(const SceneHandle& scene, const RenderTextureHandle* target) : scene_(scene.mutex) {
    std::vector<const RenderTextureHandle*> order;
    for (const auto& sampled : scene.render_textures) order.push_back(sampled.get());
    if (target != nullptr) order.push_back(target);
    std::sort(order.begin(), order.end());
    order.erase(std::unique(order.begin(), order.end()), order.end());
    // A scene sampling its own target is locked once, exclusively; the renderer then refuses
    // the frame.
    for (const RenderTextureHandle* handle : order) {
      if (handle == target) {
        target_ = std::unique_lock(handle->mutex);
      } else {
        sampled_.emplace_back(handle->mutex);
      }
    }
  }

 private:
  std::shared_lock<std::shared_mutex> scene_;
  std::vector<std::shared_lock<std::shared_mutex>> sampled_;
  std::unique_lock<std::shared_mutex> target_;
};

const SceneHandle& scene_argument(py::handle value, const char* function) {
  if (!py::isinstance<SceneHandle>(value)) {
    throw Error(std::string(function) + ": scene must be a facet.Scene, got " +
                std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  return value.cast<const SceneHandle&>();
}

// The camera of a width x height frame: camera_value, or for None the scene's (a loaded file's
// automatic view framed again for this aspect).
Camera frame_camera(const SceneHandle& scene, py::handle camera_value, const char* function,
                    int width, int height) {
  Camera camera;
  if (camera_value.is_none()) {
    std::shared_lock lock(scene.mutex);
    camera = scene_camera(scene.scene, static_cast<float>(width) / static_cast<float>(height));
  } else {
    camera = object_of<Camera>(camera_value, function, "camera", "Camera");
  }
  return camera_for_image(camera, width, height);
}

// facet.Renderer: a facet::Renderer and the size of the images it makes. One frame at a time
// each (the mutex); several renderers render at once.
class PyRenderer {
 public:
  PyRenderer(int width, int height, int threads, int msaa, py::handle background,
             py::handle exposure, const std::string& tone_mapping, int tile_size, bool shadows,
             int shadow_map_size, int shadow_cascades, bool reflections,
             py::handle reflection_scale)
      : width_(width), height_(height) {
    if (width < 1 || height < 1 || width > Framebuffer::kMaxSize ||
        height > Framebuffer::kMaxSize) {
      throw Error("Renderer: size " + std::to_string(width) + "x" + std::to_string(height) +
                  " is outside 1x1 .. " + std::to_string(Framebuffer::kMaxSize) + "x" +
                  std::to_string(Framebuffer::kMaxSize));
    }
    RenderSettings settings;
    settings.msaa = msaa;  // the renderer refuses counts other than 1, 2, 4, 8 and 16
    settings.threads = threads;
    settings.tile_size = tile_size;
    settings.clear_color = rgba(background, {"Renderer", "background"});
    settings.exposure = number(exposure, {"Renderer", "exposure"});
    settings.tone_mapping = tone_mapping_named(tone_mapping);
    settings.shadows = shadows;  // the renderer checks the map size and cascades
    settings.shadow_map_size = shadow_map_size;
    settings.shadow_cascades = shadow_cascades;
    settings.reflections = reflections;
    settings.reflection_scale = number(reflection_scale, {"Renderer", "reflection_scale"});
    renderer_ = std::make_unique<Renderer>(settings);  // its errors say "renderer: ..."
  }

  int width() const { return width_; }
  int height() const { return height_; }
  const RenderSettings& settings() const { return renderer_->settings(); }
  const FrameStats& stats() const { return stats_; }

  py::dict render(py::handle scene_value, py::handle camera_value, py::handle outputs,
                  const std::string& format_name, const std::string& normals_name) {
    const SceneHandle& scene = scene_argument(scene_value, "render");
    const std::vector<const OutputKind*> kinds = requested_outputs(outputs);
    const ColorFormat format = color_format(format_name);
    const NormalSpace normals = normal_space(normals_name);
    ExtraOutputs extra;
    for (const OutputKind* kind : kinds) kind->request(extra, normals);
    RenderedFrame frame{Framebuffer(width_, height_, format, DepthImage::none, extra),
                        frame_camera(scene, camera_value, "render", width_, height_)};
    std::vector<OutputValues> values;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      {
        FrameLocks locks(scene, nullptr);
        renderer_->begin_frame(frame.camera, scene.scene.lighting);
        draw_scene(*renderer_, scene.scene);
        renderer_->finish(frame.image);
      }
      stats_ = renderer_->stats();
      for (const OutputKind* kind : kinds) values.push_back(kind->take(frame));
    }
    py::dict result;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
      result[kinds[i]->name] = std::visit(
          [&](auto& v) -> py::object { return adopt(std::move(v), std::move(values[i].shape)); },
          values[i].values);
    }
    return result;
  }

  // One frame of scene into target, at target's size (not this renderer's).
  void render_to(py::handle target_value, py::handle scene_value, py::handle camera_value) {
    if (!py::isinstance<RenderTextureHandle>(target_value)) {
      throw Error("render_to: target must be a facet.RenderTexture, got " +
                  std::string(py::str(py::type::of(target_value).attr("__name__"))));
    }
    RenderTextureHandle& target = target_value.cast<RenderTextureHandle&>();
    const SceneHandle& scene = scene_argument(scene_value, "render_to");
    const Camera camera = frame_camera(scene, camera_value, "render_to", target.target.width(),
                                       target.target.height());
    py::gil_scoped_release release;
    std::lock_guard lock(mutex_);
    {
      FrameLocks locks(scene, &target);
      renderer_->begin_frame(camera, scene.scene.lighting);
      draw_scene(*renderer_, scene.scene);
      renderer_->finish(target.target);  // refuses a scene that samples target's textures
    }
    stats_ = renderer_->stats();
  }

 private:
  int width_;
  int height_;
  std::unique_ptr<Renderer> renderer_;
  FrameStats stats_;
  std::mutex mutex_;
};

py::dict stats_dict(const FrameStats& s) {
  py::dict d;
  d["triangles_in"] = s.triangles_in;
  d["culled"] = s.culled;
  d["clipped"] = s.clipped;
  d["drawn"] = s.drawn;
  d["lines_drawn"] = s.lines_drawn;
  d["points_drawn"] = s.points_drawn;
  d["pixels_shaded"] = s.pixels_shaded;
  d["ms_geometry"] = s.ms_geometry;
  d["ms_binning"] = s.ms_binning;
  d["ms_raster"] = s.ms_raster;
  d["ms_resolve"] = s.ms_resolve;
  d["ms_shadows"] = s.ms_shadows;
  d["ms_reflections"] = s.ms_reflections;
  d["ms_extra_outputs"] = s.ms_extra_outputs;
  d["ms_total"] = s.ms_total;
  d["display_referred"] = s.display_referred;
  d["tile_size"] = s.tile_size;
  return d;
}

void write_png(py::handle path, py::handle image) {
  Rgba8Image rgba8 = rgba8_image(image, {"write_png", "image"});
  if (rgba8.width > Framebuffer::kMaxSize || rgba8.height > Framebuffer::kMaxSize) {
    throw Error("write_png: image is larger than " + std::to_string(Framebuffer::kMaxSize) +
                " pixels on a side");
  }
  std::string file;
  try {
    file = py::str(py::module_::import("os").attr("fspath")(path));
  } catch (const py::error_already_set&) {
    throw Error("write_png: path must be a str or an os.PathLike");
  }
  py::gil_scoped_release release;
  Framebuffer framebuffer(rgba8.width, rgba8.height, ColorFormat::rgba8_srgb, DepthImage::none);
  framebuffer.rgba8() = std::move(rgba8.rgba);
  write_image(framebuffer, file);
}

}  // namespace

void bind_render(py::module_& m) {
  py::class_<PyRenderer>(m, "Renderer", R"doc(
Renders scenes into width x height images. threads: worker threads (0: all cores). msaa:
samples per pixel for anti-aliasing, 1 (off), 2, 4, 8 or 16; the color is resolved from them,
the other outputs take each pixel centre's surface. background: linear RGB(A) where nothing is
drawn. exposure: in stops, colors are scaled by 2^exposure. tone_mapping: how colors brighter
than white are shown, 'none' (clipped; a float color keeps them), 'pbr-neutral' (Khronos PBR
Neutral) or 'aces' (ACES filmic); the background color is not mapped. tile_size: 16, 32, 64 or
128, or 0 (the default) to choose it each frame: 128 where the tiles hold 8-bit codes, else 64
(the images are the same). shadows: directional and spot lights cast shadows through shadow
maps (each light whose casts_shadows is set, as every light made here is), shadow_map_size
texels a side (16 to 8192), shadow_cascades maps per directional light, 1 to 4, or 0 (the
default) to choose them from the view (docs/pipeline.md, "Shadows"). reflections: materials
with reflects_scene on a flat mesh mirror the scene, through a pass at reflection_scale (in
(0, 1]) of the image's width and height (docs/pipeline.md, "Reflections"); off, they reflect
the environment alone. The GIL is released while a frame renders, so renderers in several
Python threads render at once; one renderer renders one frame at a time.)doc")
      .def(py::init<int, int, int, int, py::handle, py::handle, const std::string&, int, bool, int,
                    int, bool, py::handle>(),
           py::arg("width"), py::arg("height"), py::arg("threads") = 0, py::arg("msaa") = 1,
           py::kw_only(), py::arg("background") = py::make_tuple(0.0, 0.0, 0.0, 1.0),
           py::arg("exposure") = 0.0, py::arg("tone_mapping") = "none",
           py::arg("tile_size") = RenderSettings{}.tile_size,
           py::arg("shadows") = RenderSettings{}.shadows,
           py::arg("shadow_map_size") = RenderSettings{}.shadow_map_size,
           py::arg("shadow_cascades") = RenderSettings{}.shadow_cascades,
           py::arg("reflections") = RenderSettings{}.reflections,
           py::arg("reflection_scale") = RenderSettings{}.reflection_scale)
      .def("render", &PyRenderer::render, py::arg("scene"), py::arg("camera") = py::none(),
           py::arg("outputs") = py::make_tuple("color", "depth"), py::kw_only(),
           py::arg("color_format") = "uint8", py::arg("normal_space") = "world", R"doc(
Renders scene seen through camera (default: scene.camera, or for a loaded file the same
automatic view framed for this image's aspect) with the aspect of this renderer's image (a
camera from intrinsics keeps its own), and returns a dict of NumPy arrays, one per name
in outputs (facet.OUTPUTS lists them). Every output but color holds 0 where nothing was drawn.
  color:       (H, W, 4) uint8, sRGB color with linear alpha; color_format="float": float32
               linear RGBA
  depth:       (H, W) float32, distance along the camera's view axis, scene units
  distance:    (H, W) float32, distance from the eye along the pixel's ray (orthographic: from
               the image plane)
  normal:      (H, W, 3) float32, unit normal in normal_space: "world", or "camera" (x right,
               y up, z toward the viewer)
  instance:    (H, W) uint32, the scene node drawn: the id add_mesh returned
  triangle:    (H, W) uint32, the triangle's index in its mesh + 1 (nvdiffrast's convention)
  barycentric: (H, W, 3) float32, perspective-correct weights of the triangle's vertices
  albedo:      (H, W, 4) float32, linear RGBA: base color x vertex color x texture, unlit
Each output beyond color costs a pass over the scene only when asked for (docs/outputs.md).
Row 0 is the top of the image. The arrays own their memory (no copy is made).)doc")
      .def("render_to", &PyRenderer::render_to, py::arg("target"), py::arg("scene"),
           py::arg("camera") = py::none(), R"doc(
Renders scene seen through camera into target, a facet.RenderTexture, at the target's size and
aspect (not this renderer's), with this renderer's settings (msaa, background, exposure, tone
mapping, threads). Afterwards target.read_color() / read_depth() hold the frame, and every
scene whose meshes use target.texture or target.depth_texture shows it. camera as in render().
A scene whose meshes sample target's own textures raises facet.Error, rendering nothing.
The GIL is released while the frame renders; the target is locked meanwhile: frames reading
its textures and its readbacks in other threads wait for it.)doc")
      .def_property_readonly("width", &PyRenderer::width)
      .def_property_readonly("height", &PyRenderer::height)
      .def_property_readonly("threads", [](const PyRenderer& r) { return r.settings().threads; })
      .def_property_readonly("msaa", [](const PyRenderer& r) { return r.settings().msaa; })
      .def_property_readonly("shadows", [](const PyRenderer& r) { return r.settings().shadows; })
      .def_property_readonly("shadow_map_size",
                             [](const PyRenderer& r) { return r.settings().shadow_map_size; })
      .def_property_readonly("shadow_cascades",
                             [](const PyRenderer& r) { return r.settings().shadow_cascades; })
      .def_property_readonly("reflections",
                             [](const PyRenderer& r) { return r.settings().reflections; })
      .def_property_readonly("reflection_scale",
                             [](const PyRenderer& r) { return r.settings().reflection_scale; })
      .def_property_readonly(
          "stats", [](const PyRenderer& r) { return stats_dict(r.stats()); },
          "What the last frame did: triangles in, culled, clipped, drawn, pixels shaded, and "
          "milliseconds per stage.");

  py::tuple names(kOutputs.size());
  for (std::size_t i = 0; i < kOutputs.size(); ++i) names[i] = py::str(kOutputs[i].name);
  m.attr("OUTPUTS") = names;

  m.def("write_png", &write_png, py::arg("path"), py::arg("image"), R"doc(
Writes an (H, W, 3) or (H, W, 4) uint8 image (sRGB, row 0 at the top) as a PNG, through a
temporary file renamed into place (a path ending in .ppm writes a binary PPM instead).)doc");
}

}  // namespace facet::python
