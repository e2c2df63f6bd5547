// The classic rasterizers, for learners (docs/classic/): three short ways to fill a triangle —
// a bounding box with edge-function weights, a scanline walk with an edge table and an active
// edge table, and a ray per pixel against the triangle's plane. Teaching code, not facet's
// pipeline: scalar, no tiles, nothing but the core types. Each draws a mesh with a depth
// buffer and perspective-correct interpolation of the world normal, shown as facet's normals
// view shows it (n * 0.5 + 0.5), into a plain RGBA8 + float depth image.
//
// front_end.cpp transforms, culls and (for the first two) clips and projects each triangle, and
// hands it to one of the three fills: bounding_box.cpp, scanline.cpp, ray_per_pixel.cpp.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/scene.hpp"

namespace facet::classic {

// The picture: row-major, top row first.
struct Image {
  Image(int width, int height);
  int width, height;
  std::vector<std::uint8_t> rgba;   // 4 per pixel: the nearest fragment's color; clear black
  std::vector<float> depth;         // window depth of the nearest fragment; 1 (far) where none
  std::vector<std::uint16_t> hits;  // how many triangles covered the pixel's centre
};

enum class Method { bounding_box, scanline, ray_per_pixel };

struct Options {
  Method method = Method::bounding_box;
  // On: a pixel centre exactly on an edge two triangles share is covered by exactly one of
  // them (the top-left rule in the first two, a watertight edge test in the ray caster). Off:
  // the textbook test, which covers such a centre twice (or, in the ray caster, twice or not at
  // all, as rounding falls). Each chapter shows both.
  bool fill_rule = true;
};

// Draws a triangle mesh (Topology::triangles) placed by `model`, seen by `camera`.
void draw_mesh(const Mesh& mesh, const glm::mat4& model, const Camera& camera, CullMode cull,
               const Options& options, Image& image);
// Draws every triangle mesh instance of the scene with its material's cull mode.
void draw_scene(const Scene& scene, const Camera& camera, const Options& options, Image& image);
// The first picture of each chapter: one large triangle leaning away from the camera, its
// corners' normals turned apart so the colors show the interpolation; the scene's camera
// frames it.
Scene make_triangle_scene();
// The image as an sRGB framebuffer (the bytes as they are: display values), for write_image.
Framebuffer to_framebuffer(const Image& image);

// --- What the front end hands the fills ---------------------------------------------------

// A corner on screen: pixels, y down, snapped to 1/256 pixel as facet snaps them.
struct ScreenVertex {
  float x, y;
  float z;           // window depth in [0, 1]: affine on screen, interpolated as it is
  float inv_w;       // 1 / clip w: affine on screen, what perspective correction divides by
  glm::vec3 normal;  // unit world normal: affine in space, not on screen
};

// The triangle (v[0], v[1], v[2]), clockwise on the y-down screen (positive doubled area).
void fill_bounding_box(const ScreenVertex v[3], bool fill_rule, Image& image);
void fill_scanline(const ScreenVertex v[3], bool fill_rule, Image& image);

// A corner in view space (the camera at the origin looking down -Z), for the ray caster.
struct ViewVertex {
  glm::dvec3 position;
  glm::vec3 normal;  // unit world normal
};

// The ray through each pixel centre, in view space, from the near plane (t = 0) to the far
// plane (t = 1); made once per image.
struct Rays {
  Rays(const Camera& camera, int width, int height);
  glm::dmat4 projection;                      // view space to clip space, for window depth
  std::vector<glm::dvec3> origin, direction;  // per pixel, row-major
};

// Pixels [x0, x1] x [y0, y1] (inclusive) that may see the triangle.
struct PixelBox {
  int x0, y0, x1, y1;
};

void fill_ray_per_pixel(const ViewVertex v[3], const Rays& rays, const PixelBox& box,
                        bool fill_rule, Image& image);

// A fragment at pixel (x, y): counts the hit, then keeps it if nearer than what is there (depth
// test "less"), colored by its interpolated normal. Every fill ends here.
void write_fragment(Image& image, int x, int y, float depth, glm::vec3 normal);

}  // namespace facet::classic
