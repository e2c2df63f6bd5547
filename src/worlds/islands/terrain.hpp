// The land of the islands world as a height function — islands, peaks, flattened plateaus and
// the river carved into them — and the meshes made from it: the ground (grass, sand and rock by
// height and slope), the ocean, and the river with its waterfall.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "worlds/islands/kit.hpp"

namespace facet::islands {

// Map coordinates: x east, z south (y up), in metres; sea level is y = 0.

struct IslandShape {
  glm::vec2 centre;
  glm::vec2 radii;  // of the coastline's ellipse, before the noise bends it
  float hills;      // height of the rolling lowland
  std::uint32_t seed;
};

struct Peak {
  glm::vec2 centre;
  float height;
  float radius;  // where its flanks meet the lowland
  float rugged;  // 0: a smooth dome; 1: heights vary by half with ridges and gullies
};

// An area levelled to one height (an airfield), blended into the land around it.
struct Plateau {
  glm::vec2 min, max;
  float height;
  float blend;  // metres over which it meets the land around it
};

// A point of a water course: the bed's half width there and the rise of its banks per metre
// (steep in a canyon, gentle in the lowland).
struct CoursePoint {
  glm::vec2 xz;
  float half_width;
  float bank_slope;
};

// Water flowing downhill along `course`; its surface starts at `source_level` and follows the
// land down (never climbing) to the sea.
struct WaterCourse {
  std::vector<CoursePoint> course;
  float source_level;
};

struct LandPlan {
  std::vector<IslandShape> islands;
  std::vector<Peak> peaks;
  std::vector<Plateau> plateaus;
  WaterCourse stream;  // high up, ends where it falls over the cliff into...
  WaterCourse river;   // ...the river, which starts at the foot of the falls
};

// A point on the river's surface.
struct RiverSpot {
  glm::vec3 centre;     // on the water surface
  glm::vec2 direction;  // downstream, unit, in the xz plane
  float half_width;     // of the water surface
};

class Terrain {
 public:
  explicit Terrain(const LandPlan& plan);

  float height(glm::vec2 xz) const;  // the ground, carved by the water
  glm::vec3 ground(float x, float z) const { return {x, height({x, z}), z}; }
  // Up-component of the ground's normal: 1 on flat ground, 0 on a vertical cliff.
  float flatness(glm::vec2 xz) const;
  // Distance to the nearest water course's centre line.
  float water_distance(glm::vec2 xz) const;
  // A point along the river: 0 at the foot of the falls, 1 where it reaches the sea.
  RiverSpot river_at(float fraction) const;
  glm::vec3 falls_centre() const { return falls_centre_; }
  glm::vec2 falls_centre_xz() const { return {falls_centre_.x, falls_centre_.z}; }

  // The ground over a rectangle (grass, sand and rock; the sand ends on the beach line, which
  // cuts through the grid's triangles) at levels of detail: level k keeps
  // every steps[k]-th line of a grid of `cell` metres squares (and the last line). Every level
  // has all the grid's points along the rectangle's edges, so rectangles side by side meet
  // without cracks whatever their levels.
  std::vector<Model> land(glm::vec2 min, glm::vec2 max, float cell,
                          std::span<const int> steps) const;
  // The river, the stream above the falls, the falling sheet and the foam at its foot.
  Model water() const;
  // The sea: a square of `size` metres around `centre` at sea level.
  static Model ocean(glm::vec2 centre, float size);

  // A course sampled every few metres, with the water level at each sample.
  struct Sample {
    glm::vec2 xz;
    float level;
    float half_width;
    float bank_slope;
    float distance;  // along the course from its start
  };

 private:
  float uncarved(glm::vec2 xz) const;
  // Where a course may carve, a box per run of kReachSegments segments: outside a run's box
  // they carve nothing, and carve() need not look at them.
  static constexpr std::size_t kReachSegments = 8;
  struct Box {
    glm::vec2 min, max;
  };
  using Reach = std::vector<Box>;
  static Reach reach_of(const std::vector<Sample>& course);
  static float carve(const std::vector<Sample>& course, const Reach& reach, glm::vec2 xz);
  std::vector<Sample> sample(const WaterCourse& water) const;
  void place_falls();
  Mesh falls_sheet(float& pool_edge) const;

  LandPlan plan_;
  std::vector<Sample> river_, stream_;
  Reach river_reach_, stream_reach_;
  glm::vec2 falls_foot_{0.0f}, falls_top_{0.0f};  // where the sheet meets the pool / the cliff top
  glm::vec3 falls_centre_{0.0f};
};

// The half width of water whose banks rise `bank_slope` per metre from a bed of `half_width`,
// out to where the ground stands a little above the water (so the water's edge is hidden).
float water_half_width(float half_width, float bank_slope);

}  // namespace facet::islands
