// The front end the three classic fills share (classic.hpp): per triangle, transform the corners
// to clip space, decide facing and cull, then either clip against the near and far planes and
// project to the screen (bounding box and scanline fills) or hand the view-space corners to the
// ray caster, which needs no clipping. The same steps as facet's reference rasterizer
// (src/pipeline/reference.cpp), in the same float operations where coverage depends on them, so
// the fills can be compared with it pixel for pixel.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <utility>

#include "classic/classic.hpp"

namespace facet::classic {
namespace {

struct Corner {
  glm::vec4 clip;
  glm::vec3 normal;
};

// Twice the signed area of the triangle in NDC times w0 w1 w2: its sign is the winding on
// screen even when a corner is behind the eye (Olano and Greer 1997), so facing is decided
// before clipping. Positive: counter-clockwise in OpenGL's y-up NDC, a front face.
double orientation(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
  const double ax = a.x, ay = a.y, aw = a.w, bx = b.x, by = b.y, bw = b.w;
  const double cx = c.x, cy = c.y, cw = c.w;
  return ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx);
}

// One Sutherland-Hodgman pass: keeps the part of the polygon where distance(corner) >= 0. The
// cut is computed from the inside corner, so two triangles sharing the edge get the same point.
template <class Distance>
int clip(const Corner* in, int count, Corner* out, Distance distance) {
  int n = 0;
  for (int i = 0; i < count; ++i) {
    const Corner& a = in[i];
    const Corner& b = in[(i + 1) % count];
    const float da = distance(a.clip), db = distance(b.clip);
    if (da >= 0.0f) out[n++] = a;
    if ((da >= 0.0f) != (db >= 0.0f)) {
      const Corner& from = da >= 0.0f ? a : b;
      const Corner& to = da >= 0.0f ? b : a;
      const float t = da >= 0.0f ? da / (da - db) : db / (db - da);
      out[n++] = {from.clip + (to.clip - from.clip) * t,
                  from.normal + (to.normal - from.normal) * t};
    }
  }
  return n;
}

// Perspective divide, viewport, and snapping to 1/256 pixel (round to nearest even, exact in
// float): facet's to_screen (src/pipeline/setup/setup.hpp) step for step.
ScreenVertex to_screen(const Corner& c, int width, int height) {
  const float inv_w = 1.0f / c.clip.w;
  const float sx = (c.clip.x * inv_w * 0.5f + 0.5f) * static_cast<float>(width);
  const float sy = (0.5f - c.clip.y * inv_w * 0.5f) * static_cast<float>(height);
  const auto snap = [](float p) { return std::nearbyint(p * 256.0f) / 256.0f; };
  return {snap(sx), snap(sy), c.clip.z * inv_w * 0.5f + 0.5f, inv_w, c.normal};
}

// Clips at near (z >= -w) and far (z <= w), projects, and fills the polygon as a fan.
void fill_on_screen(const Corner corners[3], bool front, const Options& options, Image& image) {
  // Each plane adds at most one corner: 3 + 2.
  Corner a[5], b[5];
  std::copy_n(corners, 3, a);
  int n = clip(a, 3, b, [](const glm::vec4& c) { return c.z + c.w; });
  n = clip(b, n, a, [](const glm::vec4& c) { return c.w - c.z; });
  for (int i = 1; i + 1 < n; ++i) {
    ScreenVertex s[3] = {to_screen(a[0], image.width, image.height),
                         to_screen(a[i], image.width, image.height),
                         to_screen(a[i + 1], image.width, image.height)};
    // The doubled area, exact in double for snapped coordinates; a piece that snapping made
    // degenerate, or flipped against the triangle's facing, covers nothing.
    const double area = (double{s[1].x} - s[0].x) * (double{s[2].y} - s[0].y) -
                        (double{s[1].y} - s[0].y) * (double{s[2].x} - s[0].x);
    if (area == 0.0 || (area < 0.0) != front) continue;
    if (area < 0.0) std::swap(s[1], s[2]);  // the fills take clockwise triangles
    if (options.method == Method::scanline) {
      fill_scanline(s, options.fill_rule, image);
    } else {
      fill_bounding_box(s, options.fill_rule, image);
    }
  }
}

// The pixels the triangle's projection can reach: its screen box, a pixel wider for rounding;
// the whole image when a corner is at or behind the eye plane, where projecting folds.
PixelBox screen_box(const Corner corners[3], int width, int height) {
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int i = 0; i < 3; ++i) {
    const glm::vec4& c = corners[i].clip;
    if (!(c.w > 0.0f)) return {0, 0, width - 1, height - 1};
    const glm::vec2 p((c.x / c.w * 0.5f + 0.5f) * width, (0.5f - c.y / c.w * 0.5f) * height);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // Clamped first: a corner just in front of the eye projects arbitrarily far.
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  lo = glm::clamp(lo, glm::vec2(-1.0f), glm::vec2(w + 1.0f, h + 1.0f));
  hi = glm::clamp(hi, glm::vec2(-1.0f), glm::vec2(w + 1.0f, h + 1.0f));
  return {std::max(0, static_cast<int>(std::floor(lo.x)) - 1),
          std::max(0, static_cast<int>(std::floor(lo.y)) - 1),
          std::min(width - 1, static_cast<int>(hi.x) + 1),
          std::min(height - 1, static_cast<int>(hi.y) + 1)};
}

}  // namespace

Image::Image(int w, int h)
    : width(w),
      height(h),
      rgba(static_cast<std::size_t>(w) * h * 4, 0),
      depth(static_cast<std::size_t>(w) * h, 1.0f),
      hits(static_cast<std::size_t>(w) * h, 0) {
  for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
}

Rays::Rays(const Camera& camera, int width, int height)
    : projection(camera.projection()),
      origin(static_cast<std::size_t>(width) * height),
      direction(origin.size()) {
  const glm::dmat4 unproject = glm::inverse(projection);
  const auto at = [&](double x, double y, double z) {
    const glm::dvec4 p = unproject * glm::dvec4(x, y, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double nx = (x + 0.5) / width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / height * 2.0;
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      origin[i] = at(nx, ny, -1.0);
      direction[i] = at(nx, ny, 1.0) - origin[i];
    }
  }
}

void write_fragment(Image& image, int x, int y, float depth, glm::vec3 normal) {
  const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
  ++image.hits[i];
  if (!(depth < image.depth[i])) return;  // depth test "less": the first of equals stays
  image.depth[i] = depth;
  const float length = glm::length(normal);
  const glm::vec3 shown = (length > 0.0f ? normal / length : normal) * 0.5f + 0.5f;
  for (int c = 0; c < 3; ++c) {
    image.rgba[i * 4 + c] = static_cast<std::uint8_t>(std::lround(shown[c] * 255.0f));
  }
}

void draw_mesh(const Mesh& mesh, const glm::mat4& model, const Camera& camera, CullMode cull,
               const Options& options, Image& image) {
  if (mesh.topology != Topology::triangles) return;
  mesh.validate();  // indices in range, an attribute per vertex
  const glm::mat4 view_model = camera.view() * model;
  const glm::mat4 clip_model = camera.projection() * view_model;
  const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(model));
  const Rays rays = options.method == Method::ray_per_pixel
                        ? Rays(camera, image.width, image.height)
                        : Rays(camera, 0, 0);
  const std::size_t count = mesh.element_count();
  for (std::size_t t = 0; t + 2 < count; t += 3) {
    glm::vec3 position[3];
    Corner corners[3];
    for (int i = 0; i < 3; ++i) {
      const std::size_t k = mesh.indices.empty() ? t + i : mesh.indices[t + i];
      position[i] = mesh.positions[k];
      corners[i].clip = clip_model * glm::vec4(position[i], 1.0f);
      if (!mesh.normals.empty()) corners[i].normal = normal_matrix * mesh.normals[k];
    }
    if (mesh.normals.empty()) {  // a face normal, as facet's pipeline gives such meshes
      const glm::vec3 face =
          normal_matrix * glm::cross(position[1] - position[0], position[2] - position[0]);
      for (Corner& c : corners) c.normal = face;
    }
    for (Corner& c : corners) {
      const float length = glm::length(c.normal);
      c.normal = length > 0.0f ? c.normal / length : c.normal;
    }
    const double facing = orientation(corners[0].clip, corners[1].clip, corners[2].clip);
    const bool front = facing > 0.0;
    if (!std::isfinite(facing) || facing == 0.0 || (cull == CullMode::back && !front) ||
        (cull == CullMode::front && front)) {
      continue;
    }
    if (options.method != Method::ray_per_pixel) {
      fill_on_screen(corners, front, options, image);
      continue;
    }
    ViewVertex v[3];
    for (int i = 0; i < 3; ++i) {
      v[i] = {glm::dvec3(view_model * glm::vec4(position[i], 1.0f)), corners[i].normal};
    }
    fill_ray_per_pixel(v, rays, screen_box(corners, image.width, image.height), options.fill_rule,
                       image);
  }
}

void draw_scene(const Scene& scene, const Camera& camera, const Options& options, Image& image) {
  for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
    const glm::mat4 model = scene.world_transform(static_cast<int>(n));
    for (const MeshInstance& instance : scene.nodes[n].instances_seen_from(model, camera)) {
      draw_mesh(*scene.meshes[instance.mesh], model, camera,
                scene.materials[instance.material].cull, options, image);
    }
  }
}

Scene make_triangle_scene() {
  Mesh mesh;
  // Leaning back (z falls with y), so equal steps on screen are unequal steps on the triangle.
  mesh.positions = {{-1.6f, -1.0f, 1.0f}, {1.6f, -1.0f, 1.0f}, {0.2f, 1.2f, -3.0f}};
  mesh.normals = {glm::normalize(glm::vec3(-1.0f, 0.2f, 0.4f)),
                  glm::normalize(glm::vec3(1.0f, -0.6f, 0.5f)),
                  glm::normalize(glm::vec3(0.0f, 1.0f, 0.1f))};
  Material material;
  material.cull = CullMode::none;
  Scene scene;
  scene.add_object(std::move(mesh), material);
  scene.camera = Camera::look_at({0.0f, 0.2f, 4.0f}, {0.0f, 0.0f, -0.6f});
  return scene;
}

Framebuffer to_framebuffer(const Image& image) {
  Framebuffer framebuffer(image.width, image.height);
  framebuffer.rgba8() = image.rgba;
  framebuffer.depth() = image.depth;
  return framebuffer;
}

}  // namespace facet::classic
