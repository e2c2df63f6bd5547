// Stage: clip. Reads triangles and segments from primitive assembly (primitive.cpp) in clip
// space and hands the clipped pieces back to it for setup.
#include "pipeline/geometry/clip.hpp"

#include <utility>

#include "pipeline/setup/fixed_point.hpp"

namespace facet::pipeline {
namespace {

// Signed distance to a plane; >= 0 is inside. Near and far follow OpenGL: -w <= z <= w.
float distance(const glm::vec4& c, int plane, const ClipBounds& b) {
  switch (plane) {
    case 0:
      return c.z + c.w;
    case 1:
      return c.w - c.z;
    case 2:
      return c.x + b.gx * c.w;
    case 3:
      return b.gx * c.w - c.x;
    case 4:
      return c.y + b.gy * c.w;
    case 5:
      return b.gy * c.w - c.y;
    default:
      return user_plane_distance(b.user_plane, c);
  }
}

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t, int varyings) {
  ClipVertex out;
  out.clip = a.clip + (b.clip - a.clip) * t;
  for (int i = 0; i < varyings; ++i)
    out.varyings[i] = a.varyings[i] + (b.varyings[i] - a.varyings[i]) * t;
  return out;
}

}  // namespace

ClipBounds guard_band_bounds(int width, int height) {
  // Screen x = (ndc + 1) / 2 * width stays within [-G, width + G] when
  // |ndc| <= 1 + 2G / width.
  return {1.0f + 2.0f * kGuardBandPixels / static_cast<float>(width),
          1.0f + 2.0f * kGuardBandPixels / static_cast<float>(height)};
}

ClipBounds guard_band_bounds(const Frame& frame) {
  ClipBounds bounds = guard_band_bounds(frame.width, frame.height);
  if (frame.clip_plane) bounds.clips_user_plane = true, bounds.user_plane = *frame.clip_plane;
  return bounds;
}

void clip_polygon(ClipPolygon& polygon, unsigned planes, const ClipBounds& bounds, int varyings) {
  ClipPolygon scratch;
  ClipPolygon* in = &polygon;
  ClipPolygon* out = &scratch;
  for (int plane = 0; plane < kClipPlaneCount && in->count >= 3; ++plane) {
    if (!(planes & (1u << plane))) continue;
    out->count = 0;
    for (int i = 0; i < in->count; ++i) {
      const ClipVertex& a = in->vertices[i];
      const ClipVertex& b = in->vertices[(i + 1) % in->count];
      float da = distance(a.clip, plane, bounds);
      float db = distance(b.clip, plane, bounds);
      if (da >= 0.0f) out->vertices[out->count++] = a;
      // Cut where the edge crosses the plane; t is computed from the inside vertex so that
      // both triangles sharing this edge get the identical new vertex.
      if ((da >= 0.0f) != (db >= 0.0f)) {
        out->vertices[out->count++] = da >= 0.0f ? lerp(a, b, da / (da - db), varyings)
                                                 : lerp(b, a, db / (db - da), varyings);
      }
    }
    std::swap(in, out);
  }
  if (in != &polygon) polygon = *in;
}

bool clip_segment(glm::vec4& a, glm::vec4& b, unsigned planes, const ClipBounds& bounds) {
  for (int plane = 0; plane < kClipPlaneCount; ++plane) {
    if (!(planes & (1u << plane))) continue;
    float da = distance(a, plane, bounds);
    float db = distance(b, plane, bounds);
    if (da < 0.0f && db < 0.0f) return false;
    if (da < 0.0f) a = b + (a - b) * (db / (db - da));
    if (db < 0.0f) b = a + (b - a) * (da / (da - db));
  }
  return true;
}

}  // namespace facet::pipeline
