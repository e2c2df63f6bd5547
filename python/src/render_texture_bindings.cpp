// facet.RenderTexture and facet.Texture: offscreen targets that Renderer.render_to renders into
// (render_bindings.cpp), read back as NumPy arrays, and whose textures later scenes' meshes
// sample (Scene.add_mesh's texture). Readbacks copy the image under the target's lock
// (RenderTextureHandle) with the GIL released, then hand the copy over as an array.
#include <memory>
#include <shared_mutex>
#include <string>
#include <vector>

#include "array_conversion.hpp"
#include "bindings.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render_texture.hpp"

namespace facet::python {
namespace {

ColorFormat color_format(const std::string& name) {
  if (name == "uint8") return ColorFormat::rgba8_srgb;
  if (name == "float") return ColorFormat::rgba32f;
  throw Error("RenderTexture: color_format must be 'uint8' or 'float', got '" + name + "'");
}

std::shared_ptr<RenderTextureHandle> make_render_texture(int width, int height,
                                                         const std::string& format, bool mipmaps,
                                                         bool depth, bool color,
                                                         bool srgb_texture) {
  RenderTextureOptions options;
  options.format = color_format(format);
  options.mipmaps = mipmaps;
  options.depth = depth;
  options.color = color;
  options.srgb_texture = srgb_texture;
  if (!color && !depth) {
    throw Error("RenderTexture: keeps neither color nor depth (color=False needs depth=True)");
  }
  try {
    return std::make_shared<RenderTextureHandle>(width, height, options);
  } catch (const Error& e) {
    throw Error(std::string("RenderTexture: ") + e.what());  // the library's size/option check
  }
}

// "color": H x W x 4, uint8 sRGB with linear alpha or float32 linear RGBA, as render's color.
py::object read_color(const RenderTextureHandle& handle) {
  const RenderTexture& target = handle.target;
  if (!target.options().color) {
    throw Error("RenderTexture.read_color: this render texture keeps no color (color=False)");
  }
  std::vector<py::ssize_t> shape{target.height(), target.width(), 4};
  if (target.options().format == ColorFormat::rgba32f) {
    std::vector<float> rgba;
    {
      py::gil_scoped_release release;
      std::shared_lock lock(handle.mutex);
      rgba = target.texture()->level(0).rgba32f;
    }
    return adopt(std::move(rgba), std::move(shape));
  }
  std::vector<std::uint8_t> rgba;
  {
    py::gil_scoped_release release;
    std::shared_lock lock(handle.mutex);
    rgba = target.texture()->level(0).rgba8;
  }
  return adopt(std::move(rgba), std::move(shape));
}

// "depth": H x W float32 window depth, what depth_texture holds.
py::object read_depth(const RenderTextureHandle& handle) {
  const RenderTexture& target = handle.target;
  if (!target.options().depth) {
    throw Error("RenderTexture.read_depth: this render texture keeps no depth (depth=False)");
  }
  std::vector<float> depth;
  {
    py::gil_scoped_release release;
    std::shared_lock lock(handle.mutex);
    depth = target.depth_texture()->level(0).r32f;
  }
  return adopt(std::move(depth), {target.height(), target.width()});
}

// One of the target's textures as a facet.Texture, or None when it keeps no such image.
py::object texture_of(const std::shared_ptr<RenderTextureHandle>& handle,
                      std::shared_ptr<const Texture> texture) {
  if (!texture) return py::none();
  return py::cast(TextureHandle{std::move(texture), handle});
}

}  // namespace

void bind_render_texture(py::module_& m) {
  py::class_<TextureHandle>(m, "Texture", R"doc(
A texture a mesh's material samples: RenderTexture.texture or .depth_texture, given to
Scene.add_mesh as its texture. It is the render texture's image, rewritten by every frame
rendered into it, so scenes using it show the latest one.)doc")
      .def_property_readonly("width", [](const TextureHandle& t) { return t.texture->width(); })
      .def_property_readonly("height", [](const TextureHandle& t) { return t.texture->height(); })
      .def_property_readonly(
          "levels", [](const TextureHandle& t) { return t.texture->level_count(); },
          "Mip levels: 1 (the image alone), or the whole chain down to 1x1.")
      .def("__repr__", [](const TextureHandle& t) {
        return "<facet.Texture " + t.texture->name() + " " + std::to_string(t.texture->width()) +
               "x" + std::to_string(t.texture->height()) + ">";
      });

  // Built once, so that the size limit in it is the library's.
  static const std::string render_texture_doc = R"doc(
An offscreen target: Renderer.render_to renders a frame into it, read_color() and read_depth()
read that frame back, and its texture (and depth_texture) is what later frames' meshes sample
(Scene.add_mesh(..., texture=target.texture)): a mirror, a screen inside a scene, a light's
depth. The textures are the same objects for the target's whole life, rewritten by each frame
rendered into it.

color_format: 'uint8' (sRGB, as a PNG) or 'float' (linear RGBA). mipmaps: the texture keeps its
whole mip chain, refreshed after every frame, for meshes that show it minified (their sampling
is trilinear); otherwise the image alone. depth: also keep the frame's depth (read_depth,
depth_texture). color: False keeps the depth alone (with depth=True), as a shadow map is made.
srgb_texture: for 'uint8', False makes the texture read each 8-bit code as code / 255 (data)
rather than as sRGB: a frame of display values alone (the 'normals' shading) stores each value
as its code, so later scenes sample the values it wrote.
facet.Error when neither color nor depth is kept, or for a side outside 1 to )doc" +
                                                std::to_string(Framebuffer::kMaxSize) + ".";
  py::class_<RenderTextureHandle, std::shared_ptr<RenderTextureHandle>>(m, "RenderTexture",
                                                                        render_texture_doc.c_str())
      .def(py::init(&make_render_texture), py::arg("width"), py::arg("height"), py::kw_only(),
           py::arg("color_format") = "uint8", py::arg("mipmaps") = false, py::arg("depth") = false,
           py::arg("color") = true, py::arg("srgb_texture") = true)
      .def_property_readonly("width", [](const RenderTextureHandle& h) { return h.target.width(); })
      .def_property_readonly("height",
                             [](const RenderTextureHandle& h) { return h.target.height(); })
      .def_property_readonly("color_format",
                             [](const RenderTextureHandle& h) {
                               return h.target.options().format == ColorFormat::rgba32f ? "float"
                                                                                        : "uint8";
                             })
      .def_property_readonly(
          "mipmaps", [](const RenderTextureHandle& h) { return h.target.options().mipmaps; })
      .def_property_readonly("depth",
                             [](const RenderTextureHandle& h) { return h.target.options().depth; })
      .def_property_readonly("color",
                             [](const RenderTextureHandle& h) { return h.target.options().color; })
      .def_property_readonly(
          "srgb_texture",
          [](const RenderTextureHandle& h) { return h.target.options().srgb_texture; })
      .def_property_readonly(
          "texture",
          [](const std::shared_ptr<RenderTextureHandle>& h) {
            return texture_of(h, h->target.texture());
          },
          "The color image as a facet.Texture; None when color=False.")
      .def_property_readonly(
          "depth_texture",
          [](const std::shared_ptr<RenderTextureHandle>& h) {
            return texture_of(h, h->target.depth_texture());
          },
          "The depth image as a facet.Texture, sampled as grey (depth, depth, depth, 1); None "
          "unless depth=True.")
      .def("read_color", &read_color, R"doc(
A copy of the last frame's color: (H, W, 4) uint8, sRGB with linear alpha, or float32 linear
RGBA for color_format='float'; row 0 is the top (render's color output). Before the first
frame: zeros.)doc")
      .def("read_depth", &read_depth, R"doc(
A copy of the last frame's depth: (H, W) float32 window depth, what depth_texture holds: 0 at
the camera's near plane, 1 at its far plane and where nothing was drawn; row 0 is the top. Not
linear in distance for a perspective camera: render's depth output (scene units) is
near * far / (far - d * (far - near)) of it where something was drawn; orthographic,
near + d * (far - near). Before the first frame: ones.)doc")
      .def("__repr__", [](const RenderTextureHandle& h) {
        const RenderTextureOptions& o = h.target.options();
        return "<facet.RenderTexture " + std::to_string(h.target.width()) + "x" +
               std::to_string(h.target.height()) + ", " +
               (o.format == ColorFormat::rgba32f ? "float" : "uint8") +
               (o.color ? "" : ", no color") + (o.depth ? ", depth" : "") +
               (o.mipmaps ? ", mipmaps" : "") + ">";
      });
}

}  // namespace facet::python
