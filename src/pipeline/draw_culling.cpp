// Stage: draw recording, frustum culling of whole draws (see draw_culling.hpp).
#include "pipeline/draw_culling.hpp"

#include <cmath>
#include <glm/glm.hpp>

namespace facet::pipeline {

std::optional<MeshBox> finite_bounds(const Mesh& mesh) {
  if (mesh.positions.empty()) return std::nullopt;
  MeshBox box{mesh.positions[0], mesh.positions[0]};
  for (const glm::vec3& p : mesh.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
    box.low = glm::min(box.low, p), box.high = glm::max(box.high, p);
  }
  return box;
}

bool box_outside_frustum(const MeshBox& box, const glm::mat4& model_view_projection) {
  const glm::vec3 &low = box.low, &high = box.high;
  // Bit i of `outside` stays set while every corner so far is outside plane i:
  // x < -w, x > w, y < -w, y > w, z < -w (near), z > w (far). The margin covers the rounding
  // by which the vertex stage's transform of a vertex may differ from this one's of a corner:
  // a float dot product of four terms errs by at most 4 ulp of the sum of their magnitudes,
  // |M| |p|, and 1e-5 of that is far above it.
  constexpr float kMargin = 1e-5f;
  glm::mat4 magnitude;
  for (int column = 0; column < 4; ++column)
    magnitude[column] = glm::abs(model_view_projection[column]);
  unsigned outside = 0x3f;
  for (int corner = 0; corner < 8 && outside != 0; ++corner) {
    const glm::vec4 p(corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y,
                      corner & 4 ? high.z : low.z, 1.0f);
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

}  // namespace facet::pipeline
