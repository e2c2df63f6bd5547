// The setup kernel (setup_batch.hpp) writes, on every SIMD target, the same triangles, planes
// and sequence entries as setup's definition one triangle at a time (below), bit for bit:
// for small, tiny (covering a pixel centre or none), large, degenerate and flipped triangles,
// vertices across the guard band, edges on the fill rule's cases, and plane values that overflow
// or are not numbers; and nothing past the chunk's region of planes changes.
#include "pipeline/setup/setup_batch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "core/simd_target.hpp"
#include "pipeline/geometry/primitive_sink.hpp"
#include "pipeline/setup/setup.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

using pipeline::ScreenVertex;

constexpr int kWidth = 1280, kHeight = 720;

constexpr std::size_t kNextRegion = 32;
constexpr pipeline::Plane kCanary{1.0f, 2.0f, 3.0f};

struct Triangle {
  ScreenVertex s[3];
  std::uint32_t vertex[3];  // into the varyings
  bool front_facing;
};

// What setup wrote into a frame of one chunk.
struct Written {
  pipeline::Frame frame;
  pipeline::GeometryChunk chunk;
  std::uint32_t dropped = 0;
};

// A frame whose chunk has room for `triangles`, and planes past it.
void make_frame(std::size_t triangles, int varyings, Written& w) {
  w.frame.width = kWidth, w.frame.height = kHeight, w.frame.tile_size = 64;
  w.frame.tiles_x = (kWidth + 63) / 64, w.frame.tiles_y = (kHeight + 63) / 64;
  w.frame.triangles.assign(triangles, {});
  // Past the region: planes another chunk's setup would be writing, which must stay as they are.
  w.frame.planes.assign(triangles * static_cast<std::size_t>(varyings) + kNextRegion, kCanary);
  w.chunk.triangles = {0, static_cast<std::uint32_t>(triangles), 0};
  w.frame.sequence.assign(triangles, {});
  w.chunk.entries = {0, static_cast<std::uint32_t>(triangles), 0};
}

// The triangles as setup's inputs: each corner its own projected vertex, whose varyings are
// those of the triangle's vertex in `values` (`varyings` floats each).
struct Inputs {
  std::vector<pipeline::ProjectedVertex> projected;
  std::vector<float> over_w;
  std::vector<std::uint32_t> vertex[3], front_facing;
};
Inputs inputs_of(const std::vector<Triangle>& triangles, const std::vector<float>& values,
                 int varyings) {
  Inputs in;
  for (const Triangle& t : triangles) {
    for (int i = 0; i < 3; ++i) {
      in.vertex[i].push_back(static_cast<std::uint32_t>(in.projected.size()));
      pipeline::ProjectedVertex p{};
      p.screen = t.s[i];
      in.projected.push_back(p);
      const float* v = values.data() + t.vertex[i] * varyings;
      in.over_w.insert(in.over_w.end(), v, v + varyings);
    }
    in.front_facing.push_back(t.front_facing ? 1 : 0);
  }
  in.over_w.resize(in.over_w.size() + pipeline::kOverWSlack);
  return in;
}

// Setup's definition, one triangle at a time and plainly: the oracle the kernel is held to.
// Drops a triangle that snapped to nothing or to the other winding, whose pixel box is empty,
// or that is small and covers none of its box's pixel centres; otherwise writes its edge
// functions (top-left rule folded into c), pixel box, and depth, 1 / w and varying planes.
bool set_up_by_definition(pipeline::PrimitiveSink& out, std::uint32_t draw,
                          const ScreenVertex screen[3], const float* const over_w[3], int varyings,
                          bool front_facing) {
  using namespace pipeline;
  ScreenVertex s[3] = {screen[0], screen[1], screen[2]};
  const float* values[3] = {over_w[0], over_w[1], over_w[2]};
  const std::int64_t area = signed_area(s[0], s[1], s[2]);
  if (area == 0 || (area < 0) != front_facing) return false;
  if (area < 0) std::swap(s[1], s[2]), std::swap(values[1], values[2]);
  SetupTriangle t;
  const std::int64_t min_x = std::min({s[0].x, s[1].x, s[2].x});
  const std::int64_t max_x = std::max({s[0].x, s[1].x, s[2].x});
  const std::int64_t min_y = std::min({s[0].y, s[1].y, s[2].y});
  const std::int64_t max_y = std::max({s[0].y, s[1].y, s[2].y});
  t.min_x = std::max(0, first_centre_at_or_after(min_x));
  t.min_y = std::max(0, first_centre_at_or_after(min_y));
  t.max_x = std::min(kWidth - 1, last_centre_at_or_before(max_x));
  t.max_y = std::min(kHeight - 1, last_centre_at_or_before(max_y));
  if (t.min_x > t.max_x || t.min_y > t.max_y) return false;
  for (int i = 0; i < 3; ++i) {
    const ScreenVertex &p = s[i], &q = s[(i + 1) % 3];
    t.a[i] = p.y - q.y;
    t.b[i] = q.x - p.x;
    const std::int64_t bias = is_top_left(q.x - p.x, q.y - p.y) ? 0 : -1;
    t.c[i] = -(std::int64_t{t.a[i]} * p.x + std::int64_t{t.b[i]} * p.y) + bias;
  }
  bool covers = false;
  for (int y = t.min_y; y <= t.max_y; ++y) {
    for (int x = t.min_x; x <= t.max_x; ++x) {
      covers = covers || (edge_at_centre(t, 0, x, y) >= 0 && edge_at_centre(t, 1, x, y) >= 0 &&
                          edge_at_centre(t, 2, x, y) >= 0);
    }
  }
  if (t.max_x - t.min_x < kProbedBoxSide && t.max_y - t.min_y < kProbedBoxSide &&
      max_x - min_x < kProbedSpan && max_y - min_y < kProbedSpan && !covers) {
    return false;
  }
  float px[3], py[3];
  for (int i = 0; i < 3; ++i) {
    px[i] = static_cast<float>(s[i].x) / kSubpixelScale;
    py[i] = static_cast<float>(s[i].y) / kSubpixelScale;
  }
  t.ref_x = px[0], t.ref_y = py[0];
  const PlaneSolver solver(px, py);
  t.z = solver.plane(s[0].z, s[1].z, s[2].z);
  t.inv_w = solver.plane(s[0].inv_w, s[1].inv_w, s[2].inv_w);
  const TriangleSlot slot = out.add_triangle(t);
  for (int k = 0; k < varyings; ++k)
    slot.planes[k] = solver.plane(values[0][k], values[1][k], values[2][k]);
  t.varying_planes = slot.plane_index;
  t.draw = draw;
  *slot.triangle = t;
  return true;
}

void one_at_a_time(const Inputs& in, int varyings, Written& w) {
  const std::size_t n = in.front_facing.size();
  make_frame(n, varyings, w);
  pipeline::PrimitiveSink sink(w.frame, w.chunk, varyings);
  for (std::size_t t = 0; t < n; ++t) {
    ScreenVertex s[3];
    const float* values[3];
    for (int i = 0; i < 3; ++i) {
      s[i] = in.projected[in.vertex[i][t]].screen;
      values[i] = in.over_w.data() + in.vertex[i][t] * varyings;
    }
    if (!set_up_by_definition(sink, 7, s, values, varyings, in.front_facing[t] != 0)) ++w.dropped;
  }
}

// Set up in runs of `run` triangles into a chunk with room for `kept` triangles, as many as
// setup keeps: the last triangles' planes end where the region does. The index arrays have
// garbage past each run's end (as culling's survivors do), which must not matter.
void batched(const Inputs& in, int varyings, int run, std::size_t kept, Written& w) {
  make_frame(kept, varyings, w);
  pipeline::PrimitiveSink sink(w.frame, w.chunk, varyings);
  const pipeline::SetupBatchKernel kernel = pipeline::setup_batch_kernel(chosen_simd_target());
  const std::size_t n = in.front_facing.size();
  std::vector<std::uint32_t> vertex[3], front_facing;
  for (std::size_t first = 0; first < n; first += run) {
    const int count = static_cast<int>(std::min<std::size_t>(run, n - first));
    const auto copy = [&](const std::vector<std::uint32_t>& from, std::vector<std::uint32_t>& to) {
      to.assign(count + pipeline::kSetupBatchSlack, 0xdeadbeefu);
      std::copy_n(from.begin() + first, count, to.begin());
    };
    for (int i = 0; i < 3; ++i) copy(in.vertex[i], vertex[i]);
    copy(in.front_facing, front_facing);
    const pipeline::SetupBatch batch{
        count, {vertex[0].data(), vertex[1].data(), vertex[2].data()}, front_facing.data()};
    w.dropped +=
        kernel(batch, {sink, kWidth, kHeight, 7, in.projected.data(), in.over_w.data(), varyings});
  }
}

bool same_bytes(const void* a, const void* b, std::size_t n) { return std::memcmp(a, b, n) == 0; }

// Random triangles of every kind setup meets.
std::vector<Triangle> awkward_triangles(std::mt19937& rng, std::uint32_t vertices) {
  constexpr int kScale = pipeline::kSubpixelScale;
  constexpr int kGuard = 8192 * kScale;
  std::uniform_int_distribution<int> across_x(-kGuard, kWidth * kScale + kGuard);
  std::uniform_int_distribution<int> across_y(-kGuard, kHeight * kScale + kGuard);
  std::uniform_int_distribution<int> on_screen_x(-4 * kScale, (kWidth + 4) * kScale);
  std::uniform_int_distribution<int> on_screen_y(-4 * kScale, (kHeight + 4) * kScale);
  std::uniform_int_distribution<int> nearby(-6 * kScale, 6 * kScale);
  std::uniform_int_distribution<int> tiny(-3 * kScale / 2, 3 * kScale / 2);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float specials[] = {0.0f,
                            -0.0f,
                            1e-30f,
                            3e38f,
                            -3e38f,
                            std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
  std::vector<Triangle> out(4000);
  for (Triangle& t : out) {
    const int kind = static_cast<int>(rng() % 7);
    for (int i = 0; i < 3; ++i) {
      if (kind == 0) {  // anywhere in the guard band
        t.s[i].x = across_x(rng), t.s[i].y = across_y(rng);
      } else if (kind == 5) {  // on the pixel grid: edges along rows and columns, on centres
        t.s[i].x = (on_screen_x(rng) / kScale) * kScale + (rng() % 2) * kScale / 2;
        t.s[i].y = (on_screen_y(rng) / kScale) * kScale + (rng() % 2) * kScale / 2;
      } else if (i == 0) {
        t.s[i].x = on_screen_x(rng), t.s[i].y = on_screen_y(rng);
      } else if (kind == 6) {  // within a pixel or two: often between pixel centres, or
        // on the half-pixel grid with vertex 0, edges through centres
        const int step = rng() % 2 ? 1 : kScale / 2;
        t.s[i].x = t.s[0].x + tiny(rng) / step * step,
        t.s[i].y = t.s[0].y + tiny(rng) / step * step;
      } else {  // a few pixels from vertex 0; sometimes on it (degenerate)
        t.s[i].x = t.s[0].x + (kind == 1 && rng() % 4 == 0 ? 0 : nearby(rng));
        t.s[i].y = t.s[0].y + (kind == 1 && rng() % 4 == 0 ? 0 : nearby(rng));
      }
      t.s[i].z = rng() % 32 == 0 ? specials[rng() % std::size(specials)] : unit(rng);
      t.s[i].inv_w = rng() % 32 == 0 ? specials[rng() % std::size(specials)] : unit(rng) * 4.0f;
      t.vertex[i] = static_cast<std::uint32_t>(rng() % vertices);
    }
    if (kind == 4) t.s[2] = t.s[1];     // a repeated vertex
    if (kind == 6 && rng() % 2 == 0) {  // onto the half-pixel grid, keeping the shape
      const int dx = t.s[0].x % (kScale / 2), dy = t.s[0].y % (kScale / 2);
      for (ScreenVertex& v : t.s) v.x -= dx, v.y -= dy;
    }
    // Mostly the facing the winding says; sometimes the other (as after snapping a sliver).
    const bool clockwise = pipeline::signed_area(t.s[0], t.s[1], t.s[2]) > 0;
    t.front_facing = (rng() % 8 == 0) == clockwise;
  }
  // Long slivers whose pixel boxes the frame's corners clamp to one pixel, whose centre they
  // miss: small boxes, but not probed (they span more than kProbedSpan), so kept.
  for (int corner = 0; corner < 2; ++corner) {
    Triangle t{};
    const int far = -1000 * kScale;
    const int xs[3] = {far, kScale, far}, ys[3] = {kScale * 6 / 10, far, far};
    for (int i = 0; i < 3; ++i) {
      t.s[i].x = corner == 0 ? xs[i] : kWidth * kScale - xs[i];
      t.s[i].y = corner == 0 ? ys[i] : kHeight * kScale - ys[i];
      t.s[i].z = 0.5f, t.s[i].inv_w = 1.0f;
    }
    t.front_facing = pipeline::signed_area(t.s[0], t.s[1], t.s[2]) < 0;
    out.push_back(t);
  }
  return out;
}

TEST(SetupBatch, WritesWhatTheDefinitionWritesOnEveryTarget) {
  std::mt19937 rng(11);
  constexpr std::uint32_t kVertices = 500;
  const std::vector<Triangle> triangles = awkward_triangles(rng, kVertices);
  for (int varyings : {0, 1, 3, 6, 8, 9, 16}) {
    std::vector<float> over_w(kVertices * varyings + pipeline::kOverWSlack);
    std::uniform_real_distribution<float> value(-2.0f, 2.0f);
    for (float& v : over_w) {
      v = rng() % 64 == 0 ? (rng() % 2 ? 3e38f : std::numeric_limits<float>::quiet_NaN())
                          : value(rng);
    }
    const Inputs in = inputs_of(triangles, over_w, varyings);
    Written expected;
    one_at_a_time(in, varyings, expected);
    ASSERT_GT(expected.dropped, 100u);  // the awkward cases are there
    ASSERT_GT(expected.chunk.triangles.used, 2000u);
    for (std::int64_t target : simd_targets()) {
      ForcedTarget forced(target);
      SCOPED_TRACE(hwy::TargetName(target) + std::string(", varyings ") + std::to_string(varyings));
      Written got;
      // Runs of a few triangles (a vector and a part), and as long as culling's.
      batched(in, varyings, varyings % 2 == 0 ? 11 : 128, expected.chunk.triangles.used, got);
      EXPECT_EQ(got.dropped, expected.dropped);
      ASSERT_EQ(got.chunk.triangles.used, expected.chunk.triangles.used);
      const std::size_t n = expected.chunk.triangles.used;
      for (std::size_t i = 0; i < n; ++i) {
        ASSERT_TRUE(same_bytes(&got.frame.triangles[i], &expected.frame.triangles[i],
                               sizeof(pipeline::SetupTriangle)))
            << "triangle " << i;
      }
      EXPECT_TRUE(same_bytes(got.frame.planes.data(), expected.frame.planes.data(),
                             n * varyings * sizeof(pipeline::Plane)));
      for (std::size_t i = got.frame.planes.size() - kNextRegion; i < got.frame.planes.size(); ++i)
        EXPECT_TRUE(same_bytes(&got.frame.planes[i], &kCanary, sizeof kCanary)) << "plane " << i;
      ASSERT_EQ(got.chunk.entry_count(), expected.chunk.entry_count());
      ASSERT_EQ(got.chunk.entries.used, n);
      EXPECT_TRUE(same_bytes(got.frame.sequence.data(), expected.frame.sequence.data(),
                             n * sizeof(pipeline::SequenceEntry)));
    }
  }
}

}  // namespace
}  // namespace facet::test
