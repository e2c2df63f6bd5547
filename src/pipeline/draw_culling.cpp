// Stage: draw recording, frustum culling of whole draws (see draw_culling.hpp).
#include "pipeline/draw_culling.hpp"

#include <cmath>
#include <glm/glm.hpp>

namespace facet::pipeline {

bool draw_outside_frustum(const Mesh& mesh, const glm::mat4& model_view_projection) {
  if (mesh.positions.empty()) return false;
  glm::vec3 low = mesh.positions[0], high = low;
  for (const glm::vec3& p : mesh.positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    low = glm::min(low, p), high = glm::max(high, p);
  }
  // Bit i of `outside` stays set while every corner so far is outside plane i:
  // x < -w, x > w, y < -w, y > w, z < -w (near), z > w (far). The margin covers the rounding
  // by which the vertex stage's transform of a vertex may differ from this one's of a corner.
  constexpr float kMargin = 1e-4f;
  unsigned outside = 0x3f;
  for (int corner = 0; corner < 8 && outside != 0; ++corner) {
    const glm::vec4 c =
        model_view_projection * glm::vec4(corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y,
                                          corner & 4 ? high.z : low.z, 1.0f);
    const float margin = kMargin * std::abs(c.w);
    unsigned planes = 0;
    if (c.x + c.w < -margin) planes |= 1;
    if (c.w - c.x < -margin) planes |= 2;
    if (c.y + c.w < -margin) planes |= 4;
    if (c.w - c.y < -margin) planes |= 8;
    if (c.z + c.w < -margin) planes |= 16;
    if (c.w - c.z < -margin) planes |= 32;
    outside &= planes;
  }
  return outside != 0;
}

}  // namespace facet::pipeline
