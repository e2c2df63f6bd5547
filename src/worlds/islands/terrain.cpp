// The land's height function (see terrain.hpp): islands with noisy coasts and rolling hills,
// peaks added on top, plateaus levelled, and the water courses carved in last — the land is
// the lowest of itself and every course's channel.
#include "worlds/islands/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "facet/error.hpp"
#include "worlds/islands/noise.hpp"

namespace facet::islands {
namespace {

constexpr float kSeaFloor = -12.0f;
constexpr float kShoreRise = 25.0f;       // metres of height per unit of "inland-ness" at the coast
constexpr float kBeachTop = 1.5f;         // the shore profile's height where the hills begin
constexpr float kBedDepth = 1.0f;         // river bed below the water surface
constexpr float kBankCurve = 0.02f;       // banks steepen quadratically: valleys, not trenches
constexpr float kCarveReach = 62.0f;      // banks there stand above any land (0.02 * 62² = 77 m)
constexpr float kBelowLand = 0.8f;        // the water surface sits this far below the land
constexpr float kMouthLevel = -0.3f;      // the river's surface slips under the sea's at its mouth
constexpr float kSampleSpacing = 2.0f;    // metres between course samples
constexpr float kEdgeAboveWater = 0.35f;  // ground at the water's edge, above the surface

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Sea floor, shore, beach and lowland hills of one island.
float island_height(const IslandShape& island, glm::vec2 p) {
  const glm::vec2 q = (p - island.centre) / island.radii;
  const float bend = 0.18f * (fbm(p.x / 45.0f, p.y / 45.0f, 4, island.seed) - 0.5f);
  const float inland = 1.0f - (glm::length(q) + bend);  // 0 on the coastline
  const float beach_start = kBeachTop / kShoreRise;
  // A straight shore profile: the sea meets the land at a clear angle, so the waterline is a
  // clean line instead of a band where sea and sand fight over depth.
  if (inland <= beach_start) return std::max(kShoreRise * inland, kSeaFloor);
  const float rolling = 0.35f + 0.65f * fbm(p.x / 70.0f, p.y / 70.0f, 4, island.seed + 7);
  return kBeachTop + 4.0f * (inland - beach_start) +
         island.hills * smoothstep(beach_start, 0.45f, inland) * rolling;
}

float peak_height(const Peak& peak, glm::vec2 p, std::uint32_t seed) {
  const float r = glm::length(p - peak.centre) / peak.radius;
  if (r >= 1.0f) return 0.0f;
  const float ridges = ridged(p.x / 25.0f, p.y / 25.0f, 4, seed);
  return peak.height * std::pow(smoothstep(1.0f, 0.0f, r), 1.3f) *
         (1.0f + peak.rugged * (ridges - 0.5f));
}

float plateau_weight(const Plateau& plateau, glm::vec2 p) {
  const glm::vec2 outside = glm::max(glm::max(plateau.min - p, p - plateau.max), glm::vec2(0.0f));
  return 1.0f - smoothstep(0.0f, plateau.blend, glm::length(outside));
}

glm::vec2 catmull_rom(glm::vec2 p0, glm::vec2 p1, glm::vec2 p2, glm::vec2 p3, float t) {
  const float t2 = t * t, t3 = t2 * t;
  return 0.5f * (2.0f * p1 + (p2 - p0) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                 (3.0f * p1 - p0 - 3.0f * p2 + p3) * t3);
}

// The height of a channel's ground at `bank` metres beyond the edge of its bed.
float channel_height(float level, float bank_slope, float bank) {
  return level - kBedDepth + bank_slope * bank + kBankCurve * bank * bank;
}

// Solves channel_height(level, slope, x) = level + rise for x >= 0.
float bank_distance(float bank_slope, float rise) {
  const float c = rise + kBedDepth;
  return (-bank_slope + std::sqrt(bank_slope * bank_slope + 4.0f * kBankCurve * c)) /
         (2.0f * kBankCurve);
}

}  // namespace

float water_half_width(float half_width, float bank_slope) {
  return half_width + bank_distance(bank_slope, kEdgeAboveWater);
}

Terrain::Terrain(const LandPlan& plan) : plan_(plan) {
  if (plan.river.course.size() < 2 || plan.stream.course.size() < 2) {
    throw Error("islands: the river and the stream need at least two points each");
  }
  river_ = sample(plan.river);
  stream_ = sample(plan.stream);
  place_falls();
  river_reach_ = reach_of(river_);
  stream_reach_ = reach_of(stream_);
}

float Terrain::uncarved(glm::vec2 p) const {
  float h = kSeaFloor;
  for (const IslandShape& island : plan_.islands) h = std::max(h, island_height(island, p));
  std::uint32_t seed = 100;
  for (const Peak& peak : plan_.peaks) h += peak_height(peak, p, seed++);
  for (const Plateau& plateau : plan_.plateaus) {
    h = h + (plateau.height - h) * plateau_weight(plateau, p);
  }
  return h;
}

Terrain::Reach Terrain::reach_of(const std::vector<Sample>& course) {
  // carve() skips a segment whose bed's edge lies more than kCarveReach from the point; the
  // segment lies in the box of its two samples, so that box grown by kCarveReach and the widest
  // bed (and a segment's length, to spare) is conservative: carve() gives the same with the
  // boxes or without them.
  Reach reach;
  for (std::size_t first = 0; first + 1 < course.size(); first += kReachSegments) {
    const std::size_t last = std::min(first + kReachSegments, course.size() - 1);
    Box box{course[first].xz, course[first].xz};
    float widest = 0.0f;
    for (std::size_t i = first; i <= last; ++i) {
      box.min = glm::min(box.min, course[i].xz), box.max = glm::max(box.max, course[i].xz);
      widest = std::max(widest, course[i].half_width);
    }
    const glm::vec2 margin(kCarveReach + 2.0f * widest + kSampleSpacing);
    reach.push_back({box.min - margin, box.max + margin});
  }
  return reach;
}

float Terrain::carve(const std::vector<Sample>& course, const Reach& reach, glm::vec2 p) {
  float lowest = std::numeric_limits<float>::max();
  for (std::size_t run = 0; run < reach.size(); ++run) {
    const Box& box = reach[run];
    if (p.x < box.min.x || p.y < box.min.y || p.x > box.max.x || p.y > box.max.y) continue;
    const std::size_t end = std::min((run + 1) * kReachSegments, course.size() - 1);
    for (std::size_t i = run * kReachSegments; i < end; ++i) {
      const Sample &a = course[i], &b = course[i + 1];
      const glm::vec2 ab = b.xz - a.xz;
      if (std::abs(p.x - a.xz.x) > kCarveReach + 2.0f * a.half_width + kSampleSpacing) continue;
      const float t =
          std::clamp(glm::dot(p - a.xz, ab) / std::max(glm::dot(ab, ab), 1e-6f), 0.0f, 1.0f);
      const float d = glm::length(p - (a.xz + t * ab));
      const float bank = std::max(0.0f, d - (a.half_width + t * (b.half_width - a.half_width)));
      if (bank > kCarveReach) continue;
      const float level = a.level + t * (b.level - a.level);
      const float slope = a.bank_slope + t * (b.bank_slope - a.bank_slope);
      lowest = std::min(lowest, channel_height(level, slope, bank));
    }
  }
  return lowest;
}

float Terrain::height(glm::vec2 p) const {
  return std::min({uncarved(p), carve(river_, river_reach_, p), carve(stream_, stream_reach_, p)});
}

float Terrain::flatness(glm::vec2 p) const {
  constexpr float e = 0.5f;
  const glm::vec3 n(height(p - glm::vec2(e, 0)) - height(p + glm::vec2(e, 0)), 2.0f * e,
                    height(p - glm::vec2(0, e)) - height(p + glm::vec2(0, e)));
  return glm::normalize(n).y;
}

float Terrain::water_distance(glm::vec2 p) const {
  float nearest = std::numeric_limits<float>::max();
  for (const auto* course : {&river_, &stream_}) {
    for (const Sample& s : *course) nearest = std::min(nearest, glm::length(p - s.xz));
  }
  return nearest;
}

std::vector<Terrain::Sample> Terrain::sample(const WaterCourse& water) const {
  const auto& pts = water.course;
  const int n = static_cast<int>(pts.size());
  std::vector<Sample> out;
  for (int i = 0; i + 1 < n; ++i) {
    const CoursePoint &a = pts[i], &b = pts[i + 1];
    const glm::vec2 before = pts[std::max(i - 1, 0)].xz, after = pts[std::min(i + 2, n - 1)].xz;
    const int steps =
        std::max(1, static_cast<int>(std::ceil(glm::length(b.xz - a.xz) / kSampleSpacing)));
    for (int k = 0; k < steps || (i + 2 == n && k == steps); ++k) {
      const float t = static_cast<float>(k) / steps;
      Sample s{catmull_rom(before, a.xz, b.xz, after, t), 0.0f,
               a.half_width + t * (b.half_width - a.half_width),
               a.bank_slope + t * (b.bank_slope - a.bank_slope), 0.0f};
      if (!out.empty()) s.distance = out.back().distance + glm::length(s.xz - out.back().xz);
      out.push_back(s);
    }
  }
  // Water never flows uphill: the surface is the lowest the land has been so far.
  float level = water.source_level;
  for (Sample& s : out) {
    level = std::min(level, uncarved(s.xz) - kBelowLand);
    s.level = std::max(level, kMouthLevel);
  }
  return out;
}

// The falls drop from the stream to the river's first sample. The cliff is the river's channel
// rising around that point, so the sheet's top is where that rise reaches the stream's level;
// the stream is cut back to there.
void Terrain::place_falls() {
  const Sample& foot = river_.front();
  const std::vector<CoursePoint>& stream = plan_.stream.course;
  const glm::vec2 up = glm::normalize(stream[stream.size() - 2].xz - foot.xz);
  const float top_level = stream_.back().level;
  const float reach = foot.half_width + bank_distance(foot.bank_slope, top_level - foot.level);
  falls_foot_ = foot.xz;
  falls_top_ = foot.xz + up * reach;
  while (stream_.size() > 1 && glm::length(stream_.back().xz - foot.xz) < reach) {
    stream_.pop_back();
  }
  Sample top = stream_.back();
  top.distance += glm::length(falls_top_ - top.xz);
  top.xz = falls_top_;
  top.level = top_level;
  stream_.push_back(top);
  const glm::vec2 middle = foot.xz + up * (0.5f * reach);
  falls_centre_ = {middle.x, 0.5f * (foot.level + top_level), middle.y};
}

RiverSpot Terrain::river_at(float fraction) const {
  const float s = std::clamp(fraction, 0.0f, 1.0f) * river_.back().distance;
  std::size_t i = 0;
  while (i + 2 < river_.size() && river_[i + 1].distance < s) ++i;
  const Sample &a = river_[i], &b = river_[i + 1];
  const float t =
      std::clamp((s - a.distance) / std::max(b.distance - a.distance, 1e-6f), 0.0f, 1.0f);
  const glm::vec2 xz = a.xz + t * (b.xz - a.xz);
  const float level = a.level + t * (b.level - a.level);
  return {{xz.x, level, xz.y},
          glm::normalize(b.xz - a.xz),
          water_half_width(a.half_width, a.bank_slope)};
}

}  // namespace facet::islands
