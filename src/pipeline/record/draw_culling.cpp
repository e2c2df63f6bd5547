// Stage: draw recording, frustum culling of whole draws (see draw_culling.hpp).
#include "pipeline/record/draw_culling.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/glm.hpp>

namespace facet::pipeline {

std::optional<MeshBox> finite_bounds(const Mesh& mesh) {
  if (mesh.positions.empty()) return std::nullopt;
  // Every draw of every frame calls this on the recording thread, so it goes four vertices
  // (twelve floats, three four-lane vectors) a step over the coordinates as one flat array,
  // with no early exit. Each lane keeps its own bounds and a sum of c - c, which stays 0 while
  // every c is finite (infinities and NaN make it NaN). GCC's vector extension: plain SSE.
  using Lanes = float __attribute__((vector_size(16)));
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
  const float* c = &mesh.positions[0].x;
  const std::size_t count = 3 * mesh.positions.size();
  // Lane j of vector k holds coordinate (4k + j) % 3; the start values follow that pattern.
  Lanes low[3], high[3], infinite[3] = {};
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 4; ++j) low[k][j] = high[k][j] = c[(4 * k + j) % 3];
  }
  std::size_t i = 0;
  for (; i + 12 <= count; i += 12) {
    for (int k = 0; k < 3; ++k) {
      Lanes x;
      std::memcpy(&x, c + i + 4 * k, sizeof x);
      low[k] = x < low[k] ? x : low[k];
      high[k] = x > high[k] ? x : high[k];
      infinite[k] += x - x;
    }
  }
  MeshBox box{glm::vec3(c[0], c[1], c[2]), glm::vec3(c[0], c[1], c[2])};
  float sum = 0.0f;
  for (; i < count; ++i) {  // the last vertices
    box.low[i % 3] = std::min(box.low[i % 3], c[i]);
    box.high[i % 3] = std::max(box.high[i % 3], c[i]);
    sum += c[i] - c[i];
  }
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 4; ++j) {
      const int axis = (4 * k + j) % 3;
      box.low[axis] = std::min(box.low[axis], low[k][j]);
      box.high[axis] = std::max(box.high[axis], high[k][j]);
      sum += infinite[k][j];
    }
  }
  if (sum != 0.0f) return std::nullopt;  // also when it is NaN
  return box;
}

namespace {

// |M| element by element: |M| |p| bounds the magnitudes that M p sums, for the rounding margins.
glm::mat4 magnitudes(const glm::mat4& m) {
  glm::mat4 out;
  for (int column = 0; column < 4; ++column) out[column] = glm::abs(m[column]);
  return out;
}

}  // namespace

bool box_outside_frustum(const MeshBox& box, const glm::mat4& model_view_projection) {
  // Bit i of `outside` stays set while every corner so far is outside plane i:
  // x < -w, x > w, y < -w, y > w, z < -w (near), z > w (far). The margin covers the rounding
  // by which the vertex stage's transform of a vertex may differ from this one's of a corner:
  // a float dot product of four terms errs by at most 4 ulp of the sum of their magnitudes,
  // |M| |p|, and 1e-5 of that is far above it.
  constexpr float kMargin = 1e-5f;
  const glm::mat4 magnitude = magnitudes(model_view_projection);
  unsigned outside = 0x3f;
  for (int corner = 0; corner < 8 && outside != 0; ++corner) {
    const glm::vec4 p = box.corner(corner);
    const glm::vec4 c = model_view_projection * p;
    const glm::vec4 size = magnitude * glm::abs(p);
    const float x_margin = kMargin * (size.x + size.w), y_margin = kMargin * (size.y + size.w);
    const float z_margin = kMargin * (size.z + size.w);
    unsigned planes = 0;
    if (c.x + c.w < -x_margin) planes |= 1;
    if (c.w - c.x < -x_margin) planes |= 2;
    if (c.y + c.w < -y_margin) planes |= 4;
    if (c.w - c.y < -y_margin) planes |= 8;
    if (c.z + c.w < -z_margin) planes |= 16;
    if (c.w - c.z < -z_margin) planes |= 32;
    outside &= planes;
  }
  return outside != 0;
}

bool box_inside_clip_bounds(const MeshBox& box, const glm::mat4& model_view_projection,
                            const ClipBounds& guard) {
  // The outcode() tests, each a linear function of the position: positive at every corner
  // means positive all over the box. One margin for the whole box, from its largest
  // magnitudes: a vertex anywhere inside errs by a few ulp of |M| |p| <= |M| |corner|max, far
  // below 1e-5 of it (so a vertex of the box never gets a code that asks for clipping).
  constexpr float kMargin = 1e-5f;
  const glm::vec4 largest(glm::max(glm::abs(box.low), glm::abs(box.high)), 1.0f);
  const glm::vec4 size = magnitudes(model_view_projection) * largest;
  const float x_margin = kMargin * (size.x + guard.gx * size.w);
  const float y_margin = kMargin * (size.y + guard.gy * size.w);
  const float z_margin = kMargin * (size.z + size.w);
  const glm::vec4 plane = glm::abs(guard.user_plane);
  const float plane_margin =
      kMargin * (plane.x * size.x + plane.y * size.y + plane.z * size.z + plane.w * size.w);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec4 c = model_view_projection * box.corner(corner);
    const bool inside = c.z + c.w > z_margin && c.w - c.z > z_margin &&
                        c.x + guard.gx * c.w > x_margin && guard.gx * c.w - c.x > x_margin &&
                        c.y + guard.gy * c.w > y_margin && guard.gy * c.w - c.y > y_margin;
    if (!inside) return false;  // also when NaN
    if (guard.clips_user_plane && !(user_plane_distance(guard.user_plane, c) > plane_margin)) {
      return false;
    }
  }
  return true;
}

}  // namespace facet::pipeline
