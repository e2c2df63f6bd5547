// The islands world, read as a description of the map: the land and the water first, then the
// first island's village and forests, the second island's airfield, the moving things, the sky.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "facet/islands.hpp"
#include "worlds/islands/kit.hpp"
#include "worlds/islands/map.hpp"
#include "worlds/islands/noise.hpp"
#include "worlds/islands/objects.hpp"
#include "worlds/islands/terrain.hpp"
#include "worlds/islands/textures.hpp"

namespace facet {
namespace islands {
namespace {

using glm::vec2;
using glm::vec3;

constexpr float kDegrees = 180.0f / 3.14159265f;
// The haze: fog, the sky at the horizon and the sky below it are one color, so the far sea
// melts into the sky. It is the default background of `facet render` (0.53, 0.66, 0.82 sRGB),
// which that command also uses as its fog color.
constexpr vec3 kHaze{0.243f, 0.393f, 0.638f};
constexpr vec2 kHouseSite{-40.0f, 12.0f};  // on the meadow west of the river

// --- the land ----------------------------------------------------------------------------------

LandPlan land_plan() {
  LandPlan land;
  land.islands = {
      {{0, 0}, {150, 130}, 7.0f, 11},    // the first island: meadows, mountains, the river
      {{320, 70}, {90, 100}, 3.0f, 23},  // the second island: low, for the airfield
  };
  land.peaks = {
      {{35, -50}, 42.0f, 85.0f, 0.5f},      // the mountain massif in the first island's north-east
      {{15, -78}, 22.0f, 40.0f, 0.8f},      // its summit
      {{72, -46}, 18.0f, 34.0f, 0.8f},      // its eastern shoulder
      {map::kLookout, 24.0f, 42.0f, 0.0f},  // the lookout hill, where the start camera stands
  };
  land.plateaus = {{{280, 0}, {370, 140}, map::kAirfieldHeight, 12.0f}};
  // A spring high in the massif feeds a stream that falls over a cliff into the canyon.
  land.stream = {{{{66, -60}, 1.8f, 1.4f}, {{54, -47}, 2.0f, 1.8f}, {{42, -38}, 2.2f, 2.0f}},
                 28.0f};
  // The river runs from the foot of the falls down the canyon (steep banks), then across the
  // meadows (gentle banks) to the south coast.
  land.river = {{{{42, -38}, 3.5f, 3.0f},
                 {{25, -28}, 3.8f, 3.0f},
                 {{8, -18}, 4.0f, 2.0f},
                 {{-5, 5}, 3.0f, 0.8f},
                 {{-15, 35}, 3.0f, 0.7f},
                 {{-22, 70}, 3.2f, 0.6f},
                 {{-27, 110}, 3.5f, 0.6f},
                 {{-30, 150}, 4.0f, 0.6f}},
                10.0f};
  return land;
}

// The ground's levels of detail: every line of its grid near the camera, every second from
// 150 m, every fourth from 300 m (at a 60 degree field of view). That far, a square of the
// first island's grid (0.8 m) is a few pixels at most. These distances and the trees' stand-ins
// (kit.hpp) are as near as the floor allows: the start view must draw at least 100,000
// triangles at 1080p (Islands.StartViewDrawsAtLeast100kTriangles).
constexpr int kGroundSteps[] = {1, 2, 4};
constexpr float kGroundDetailFrom[] = {150.0f, 300.0f};

// The ground over a rectangle, chunk by chunk (the corners are multiples of the chunk size, and
// the chunk size of the cell, so the chunks' grids meet vertex to vertex). The chunks are made
// in parallel, most of the world's start-up (the height function), and placed in order.
void place_land(WorldBuilder& world, const Terrain& terrain, vec2 min, vec2 max, float cell) {
  const float chunk = WorldBuilder::kChunk;
  const int columns = static_cast<int>(std::ceil((max.x - min.x) / chunk));
  const int rows = static_cast<int>(std::ceil((max.y - min.y) / chunk));
  auto corner = [&](int k) { return min + chunk * vec2(k % columns, k / columns); };
  std::vector<std::vector<Model>> levels(static_cast<std::size_t>(columns * rows));
  tbb::parallel_for(0, columns * rows, [&](int k) {
    levels[k] = terrain.land(corner(k), corner(k) + vec2(chunk), cell, kGroundSteps);
  });
  for (int k = 0; k < columns * rows; ++k) {
    world.place_ground(std::move(levels[k]), kGroundDetailFrom, corner(k) + vec2(0.5f * chunk));
  }
}

// --- the first island: a house by the river, a bridge, forests --------------------------------

void build_village(WorldBuilder& world, const Terrain& terrain) {
  // The bridge crosses where the river winds through the meadows, resting on both banks.
  const RiverSpot crossing = terrain.river_at(0.4f);
  const vec2 centre(crossing.centre.x, crossing.centre.z);
  const vec2 across(-crossing.direction.y, crossing.direction.x);
  const float span = 2.0f * crossing.half_width + 8.0f;
  const float banks = std::max(terrain.height(centre + across * (0.5f * span - 1.5f)),
                               terrain.height(centre - across * (0.5f * span - 1.5f)));
  const float deck = std::max(banks, crossing.centre.y + 1.2f) + 0.25f;
  world.place(bridge(span, 3.2f),
              at({centre.x, deck, centre.y}, std::atan2(-across.y, across.x) * kDegrees));

  // The house stands on the meadow west of the river, its front toward the lookout, its floor
  // above the highest corner of its footprint (the foundation reaches down to the lowest).
  const vec2 site = kHouseSite;
  float floor = -1e9f;
  for (vec2 corner : {vec2(-5, -4), vec2(5, -4), vec2(-5, 4), vec2(5, 4)}) {
    floor = std::max(floor, terrain.height(site + corner));
  }
  const vec2 to_lookout = glm::normalize(map::kLookout - site);
  world.place(house(9.0f, 7.0f, 3.0f), at({site.x, floor - 0.25f, site.y},
                                          std::atan2(to_lookout.x, to_lookout.y) * kDegrees));
}

bool keep_clear(vec2 p) {
  // The lookout and the view from it across to the airfield stay open.
  const vec2 d = p - map::kLookout;
  const float distance = glm::length(d);
  if (distance < 24.0f) return true;
  const vec2 look = glm::normalize(map::kRunwayCentre - map::kLookout);
  if (distance < 340.0f && glm::dot(d / distance, look) > std::cos(7.0f / kDegrees)) return true;
  if (glm::length(p - kHouseSite) < 11.0f) return true;
  // The airfield.
  return p.x > 262.0f && p.x < 380.0f && p.y > -10.0f && p.y < 150.0f;
}

// One tree for a spot: palms by the beach, conifers up the slopes, broadleaf trees between.
Model tree_for(float ground, std::uint32_t seed, Detail detail) {
  const float r = random01(static_cast<int>(seed), 1, 90);
  const float size = random01(static_cast<int>(seed), 2, 90);
  if (ground < 4.5f) return palm(7.0f + 4.0f * size, seed, detail);
  if (ground > 17.0f || r < 0.25f) return conifer(7.0f + 6.0f * size, seed, detail);
  return broadleaf(6.0f + 4.0f * size, seed, detail);
}

// Trees on a jittered grid: dense in forest patches (where low noise is high), scattered
// elsewhere; never on sand, cliffs, high rock, in the water or where things must stay clear.
void plant_forest(WorldBuilder& world, const Terrain& terrain, vec2 min, vec2 max) {
  constexpr float kSpacing = 7.0f;
  for (int j = 0; min.y + j * kSpacing < max.y; ++j) {
    for (int i = 0; min.x + i * kSpacing < max.x; ++i) {
      const std::uint32_t seed = hash32(i, j, 77);
      const vec2 p =
          min + kSpacing * vec2(i + 0.8f * random01(i, j, 78), j + 0.8f * random01(i, j, 79));
      const float forest = fbm(p.x / 60.0f, p.y / 60.0f, 3, 81);
      if (forest < 0.45f && random01(i, j, 80) > 0.3f) continue;
      const float ground = terrain.height(p);
      if (ground < 2.6f || ground > 40.0f || keep_clear(p)) continue;
      if (terrain.water_distance(p) < 13.0f || terrain.flatness(p) < 0.82f) continue;
      world.place(tree_for(ground, seed, Detail::full), tree_for(ground, seed, Detail::far),
                  at({p.x, ground, p.y}, 360.0f * random01(i, j, 82)));
    }
  }
}

// Bushes on the meadows and stones on the slopes and beaches, on a finer jittered grid.
void scatter_undergrowth(WorldBuilder& world, const Terrain& terrain, vec2 min, vec2 max) {
  constexpr float kSpacing = 5.0f;
  for (int j = 0; min.y + j * kSpacing < max.y; ++j) {
    for (int i = 0; min.x + i * kSpacing < max.x; ++i) {
      const vec2 p = min + kSpacing * vec2(i + random01(i, j, 83), j + random01(i, j, 84));
      const float r = random01(i, j, 85), ground = terrain.height(p);
      if (ground < 0.5f || ground > 45.0f || keep_clear(p)) continue;
      if (terrain.water_distance(p) < 12.0f) continue;
      const std::uint32_t seed = hash32(i, j, 86);
      const float size = 0.8f + 0.8f * random01(i, j, 87);
      const glm::mat4 where = at({p.x, ground, p.y}, 360.0f * random01(i, j, 88));
      if (ground > 2.6f && ground < 25.0f && r < 0.22f && terrain.flatness(p) > 0.85f) {
        world.place(bush(size, seed), bush(size, seed, Detail::far), where);
      } else if ((ground > 20.0f || ground < 2.2f) && r < 0.12f) {
        world.place(boulder(size, seed), boulder(size, seed, Detail::far), where);
      }
    }
  }
}

// --- the second island: the airfield -----------------------------------------------------------

void build_airfield(WorldBuilder& world, IslandsWorld& out) {
  const float plateau = map::kAirfieldHeight, paved = plateau + map::kPaveLift;
  const vec2 runway_at = map::kRunwayCentre;
  world.place(runway(map::kRunwayLength, map::kRunwayWidth),
              at({runway_at.x, paved, runway_at.y}, 90.0f));
  world.place(control_tower(), at({296.0f, plateau, 96.0f}));
  world.place(windsock(), at({298.0f, plateau, 30.0f}));
  // East of the runway: the apron, and the hangar with its door facing west onto it.
  world.place(apron(50.0f, 18.0f), at({334.5f, paved, 65.0f}, 90.0f));
  world.place(hangar(24.0f, 16.0f), at({357.0f, plateau, 65.0f}, 180.0f));
  // The parked airplane waits on the apron, nose south, propeller turning.
  const Airplane parked = airplane(srgb(0.95f, 0.95f, 0.93f), srgb(0.85f, 0.15f, 0.12f), true);
  out.parked_airplane = world.add_node("parked airplane", parked.body,
                                       at({334.0f, paved + kAirplaneWheelDrop, 62.0f}, -90.0f));
  out.parked_propeller =
      world.add_node("parked propeller", parked.propeller, at(parked.hub), out.parked_airplane);
}

// --- things that move ----------------------------------------------------------------------

void add_vehicles(WorldBuilder& world, IslandsWorld& out) {
  const Airplane flyer = airplane(srgb(0.98f, 0.8f, 0.15f), srgb(0.15f, 0.3f, 0.75f), false);
  out.flying_airplane = world.add_node("flying airplane", flyer.body, glm::mat4(1.0f));
  out.flying_propeller =
      world.add_node("flying propeller", flyer.propeller, at(flyer.hub), out.flying_airplane);
  out.boat = world.add_node("boat", boat(), glm::mat4(1.0f));
}

void add_clouds(WorldBuilder& world, IslandsWorld& out) {
  for (int k = 0; k < 14; ++k) {
    const vec3 origin(map::kCloudsWest + map::kCloudsSpan * random01(k, 0, 91),
                      115.0f + 45.0f * random01(k, 1, 91), -420.0f + 700.0f * random01(k, 2, 91));
    out.clouds.push_back(world.add_node("cloud", cloud(static_cast<std::uint32_t>(k)), at(origin)));
    out.cloud_origins.push_back(origin);
  }
}

// --- sky and view --------------------------------------------------------------------------------

void set_sky(Lighting& lighting) {
  // The sun stands in the south-west, behind the start camera's right shoulder, so the falls
  // and the canyon face it.
  lighting.lights = {
      Light::directional(glm::normalize(vec3(0.55f, -0.7f, -0.45f)), {1.0f, 0.95f, 0.86f}, 1.9f)};
  lighting.ambient = {0.26f, 0.30f, 0.38f};
  lighting.environment.show_as_background = true;
  lighting.environment.sky_zenith = {0.09f, 0.22f, 0.58f};
  lighting.environment.sky_horizon = kHaze;
  lighting.environment.ground = kHaze;
  lighting.fog.mode = FogMode::exponential;
  lighting.fog.density = 0.0011f;
  lighting.fog.color = kHaze;
}

Camera start_camera(const Terrain& terrain) {
  const vec3 eye =
      terrain.ground(map::kStandpoint.x, map::kStandpoint.y) + vec3(0, map::kEyeHeight, 0);
  // Near 0.5 m keeps the depth buffer fine enough for the runway over the plateau at 400 m.
  return Camera::look_at(eye, map::kLookAt, {0, 1, 0}, map::kFieldOfView, 16.0f / 9.0f, 0.5f,
                         3000.0f);
}

IslandsWorld build_world() {
  const Terrain terrain(land_plan());
  WorldBuilder world(make_island_textures());
  world.place_last(Terrain::ocean(map::kMapCentre, 7000.0f));  // beyond the far plane every way
  place_land(world, terrain, {-180, -180}, {180, 180}, 0.8f);  // the first island
  place_land(world, terrain, {180, -60}, {420, 180}, 1.25f);   // the second island
  world.place_in_chunk(terrain.water(), terrain.falls_centre_xz());
  build_village(world, terrain);
  plant_forest(world, terrain, {-165, -145}, {165, 145});
  plant_forest(world, terrain, {220, -40}, {420, 180});
  scatter_undergrowth(world, terrain, {-165, -145}, {165, 145});
  scatter_undergrowth(world, terrain, {220, -40}, {420, 180});

  IslandsWorld out;
  build_airfield(world, out);
  add_vehicles(world, out);
  add_clouds(world, out);
  out.scene = world.finish();
  out.waterfall_material = WorldBuilder::material(Surface::falls);
  out.river_material = WorldBuilder::material(Surface::river);
  out.ocean_material = WorldBuilder::material(Surface::ocean);
  out.waterfall_centre = terrain.falls_centre();
  set_sky(out.scene.lighting);
  out.scene.camera = start_camera(terrain);
  out.scene.metres_per_unit = 1.0f;
  out.animate(0.0);
  return out;
}

}  // namespace
}  // namespace islands

IslandsWorld make_islands_world() { return islands::build_world(); }

Scene make_islands_scene() { return make_islands_world().scene; }

}  // namespace facet
