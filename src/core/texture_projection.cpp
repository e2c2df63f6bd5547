// Texture projections (see facet/mesh_tools.hpp): spherical, cylindrical, planar.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "facet/mesh_tools.hpp"

namespace facet {
namespace {

constexpr float kPi = 3.14159265358979f;

// Longitude in [0, 1): 0.5 faces +Z (toward a default camera), increasing toward +X.
float longitude(glm::vec3 d) { return 0.5f + std::atan2(d.x, d.z) / (2.0f * kPi); }

// For triangles whose u values span more than half the texture, the short way round crosses
// the seam: give their low-u vertices a copy at u + 1 (repeat wrapping makes that the same
// texel column), so interpolation runs across the seam, not back across the whole texture.
void fix_seams(Mesh& mesh) {
  if (mesh.topology != Topology::triangles) return;
  if (mesh.indices.empty()) {
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) mesh.indices.push_back(i);
  }
  auto copy_vertex = [&mesh](std::uint32_t i) {
    auto copy_attribute = [i](auto& attribute) {
      if (!attribute.empty()) attribute.push_back(attribute[i]);
    };
    copy_attribute(mesh.positions);
    copy_attribute(mesh.normals);
    copy_attribute(mesh.texcoords);
    copy_attribute(mesh.colors);
    copy_attribute(mesh.tangents);
    return static_cast<std::uint32_t>(mesh.positions.size() - 1);
  };
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::uint32_t* tri = &mesh.indices[t];
    float low = 1.0f, high = 0.0f;
    for (int k = 0; k < 3; ++k) {
      low = std::min(low, mesh.texcoords[tri[k]].x);
      high = std::max(high, mesh.texcoords[tri[k]].x);
    }
    if (high - low <= 0.5f) continue;
    for (int k = 0; k < 3; ++k) {
      if (mesh.texcoords[tri[k]].x < 0.5f) {
        std::uint32_t copy = copy_vertex(tri[k]);
        mesh.texcoords[copy].x += 1.0f;
        tri[k] = copy;
      }
    }
  }
}

}  // namespace

void project_texcoords(Mesh& mesh, TextureProjection projection, glm::vec3 centre) {
  glm::vec3 low(1e30f), high(-1e30f);
  for (const glm::vec3& p : mesh.positions) low = glm::min(low, p), high = glm::max(high, p);
  glm::vec3 size = glm::max(high - low, glm::vec3(1e-12f));
  mesh.texcoords.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    glm::vec3 p = mesh.positions[i];
    glm::vec3 d = p - centre;
    glm::vec2& uv = mesh.texcoords[i];
    switch (projection) {
      case TextureProjection::spherical: {
        float length = glm::length(d);
        glm::vec3 n = length > 0.0f ? d / length : glm::vec3(0.0f, 1.0f, 0.0f);
        uv = {longitude(n), 0.5f + std::asin(std::clamp(n.y, -1.0f, 1.0f)) / kPi};
        break;
      }
      case TextureProjection::cylindrical:
        uv = {longitude(glm::vec3(d.x, 0.0f, d.z)), (p.y - low.y) / size.y};
        break;
      case TextureProjection::planar:
        uv = {(p.x - low.x) / size.x, (p.y - low.y) / size.y};
        break;
    }
  }
  if (projection != TextureProjection::planar) fix_seams(mesh);
}

}  // namespace facet
