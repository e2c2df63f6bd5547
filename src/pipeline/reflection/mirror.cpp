// Planar reflection geometry (mirror.hpp).
#include "pipeline/reflection/mirror.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "pipeline/geometry/clip.hpp"

namespace facet::pipeline {
namespace {

float signed_distance(const glm::vec4& plane, glm::vec3 p) {
  return glm::dot(glm::vec3(plane), p) + plane.w;
}

glm::vec3 mirrored_point(const glm::vec4& plane, glm::vec3 p) {
  return p - 2.0f * signed_distance(plane, p) * glm::vec3(plane);
}

glm::vec3 mirrored_direction(const glm::vec4& plane, glm::vec3 v) {
  const glm::vec3 n(plane);
  return v - 2.0f * glm::dot(n, v) * n;
}

}  // namespace

std::optional<glm::vec4> mirror_plane(const Mesh& mesh, const glm::mat4& model, glm::vec3 eye,
                                      CullMode cull) {
  if (mesh.topology != Topology::triangles || mesh.positions.empty()) return std::nullopt;
  const auto world = [&](std::size_t i) {
    return glm::vec3(model * glm::vec4(mesh.positions[i], 1.0f));
  };
  const auto index = [&](std::size_t i) { return mesh.indices.empty() ? i : mesh.indices[i]; };
  const std::size_t corners = mesh.indices.empty() ? mesh.positions.size() : mesh.indices.size();
  // The normal of the first triangle whose area is not negligible.
  glm::vec3 low = world(0), high = low;
  for (std::size_t i = 1; i < mesh.positions.size(); ++i) {
    low = glm::min(low, world(i)), high = glm::max(high, world(i));
  }
  const float size = glm::length(high - low);
  if (!(size > 0.0f) || !std::isfinite(size)) return std::nullopt;
  glm::vec3 origin(0.0f), normal(0.0f);
  for (std::size_t t = 0; t + 2 < corners; t += 3) {
    const glm::vec3 a = world(index(t)), b = world(index(t + 1)), c = world(index(t + 2));
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    if (length > 1e-6f * size * size) {
      origin = a, normal = n / length;
      break;
    }
  }
  if (normal == glm::vec3(0.0f)) return std::nullopt;
  glm::vec4 plane(normal, -glm::dot(normal, origin));
  const float tolerance = 1e-4f * size;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!(std::abs(signed_distance(plane, world(i))) <= tolerance)) return std::nullopt;
  }
  // An eye in the plane sees the mirror edge-on (a camera low over a wide sea is not that).
  const float eye_side = signed_distance(plane, eye);
  if (std::abs(eye_side) <= 1e-6f * size) return std::nullopt;
  // The plane's normal is the first triangle's front (counter-clockwise) side, in world space.
  if ((cull == CullMode::back && eye_side < 0.0f) || (cull == CullMode::front && eye_side > 0.0f)) {
    return std::nullopt;
  }
  return eye_side > 0.0f ? plane : -plane;
}

bool same_plane(const glm::vec4& a, const glm::vec4& b) {
  const float scale = std::max({1.0f, std::abs(a.w), std::abs(b.w)});
  return glm::dot(glm::vec3(a), glm::vec3(b)) > 1.0f - 1e-5f &&
         std::abs(a.w - b.w) <= 1e-4f * scale;
}

Camera mirrored_camera(const Camera& camera, const glm::vec4& plane) {
  Camera mirrored = camera;
  mirrored.eye = mirrored_point(plane, camera.eye);
  mirrored.target = mirrored_point(plane, camera.target);
  mirrored.up = mirrored_direction(plane, camera.up);
  mirrored.lens_shift.x = -camera.lens_shift.x;
  return mirrored;
}

glm::mat4 mirror_image_transform(const Camera& mirrored) {
  // NDC -> (u, v) = (0.5 + 0.5 x, 0.5 + 0.5 y), before the divide by w.
  glm::mat4 to_image(0.0f);
  to_image[0][0] = 0.5f, to_image[3][0] = 0.5f;
  to_image[1][1] = 0.5f, to_image[3][1] = 0.5f;
  to_image[3][3] = 1.0f;
  return to_image * mirrored.view_projection();
}

glm::vec4 clip_space_plane(const glm::mat4& view_projection, const glm::vec4& world_plane) {
  // plane . p = plane . (VP^-1 c) = (VP^-T plane) . c, in double: VP's inverse loses digits.
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(view_projection));
  return glm::vec4(glm::transpose(inverse) * glm::dvec4(world_plane));
}

void add_seen_box(const MeshBox& box, const glm::mat4& model_view_projection, NdcRect& rect) {
  glm::vec4 corner[8];
  for (int k = 0; k < 8; ++k) corner[k] = model_view_projection * box.corner(k);
  // The six faces as triangles (corner bit 0 is x, 1 is y, 2 is z), each clipped to the frustum.
  static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  constexpr unsigned kFrustum =
      kClipNear | kClipFar | kClipLeft | kClipRight | kClipBottom | kClipTop;
  for (const auto& face : kFaces) {
    for (int half = 0; half < 2; ++half) {
      ClipPolygon polygon;
      polygon.count = 3;
      polygon.vertices[0].clip = corner[face[0]];
      polygon.vertices[1].clip = corner[face[1 + half]];
      polygon.vertices[2].clip = corner[face[2 + half]];
      clip_polygon(polygon, kFrustum, ClipBounds{}, 0);
      for (int i = 0; i < polygon.count && polygon.count >= 3; ++i) {
        const glm::vec4& c = polygon.vertices[i].clip;
        if (c.w > 0.0f) rect.add(glm::clamp(glm::vec2(c) / c.w, glm::vec2(-1.0f), glm::vec2(1.0f)));
      }
    }
  }
}

Camera cropped_camera(const Camera& camera, const NdcRect& rect) {
  // NDC x' = (x - centre) / half: the projection's scale divided by half, the shift moved.
  const glm::vec2 centre = (rect.low + rect.high) * 0.5f, half = (rect.high - rect.low) * 0.5f;
  Camera cropped = camera;
  cropped.aspect = camera.aspect * half.x / half.y;
  cropped.lens_shift = (camera.lens_shift - centre) / half;
  if (camera.projection_kind == Projection::orthographic) {
    cropped.view_height = camera.view_height * half.y;
  } else {
    const float tan_half = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f) * half.y;
    cropped.fov_y_degrees = glm::degrees(2.0f * std::atan(tan_half));
  }
  cropped.calibrated_size = glm::ivec2(0);
  return cropped;
}

}  // namespace facet::pipeline
