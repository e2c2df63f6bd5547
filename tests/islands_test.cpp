// The islands world: it builds, it is a real workload, its animation depends on the time alone,
// the boat and the airplane move and stay above the water, and its start view matches a golden
// image (tests/golden/islands_default.png; FACET_UPDATE_GOLDENS=1 rewrites it).
#include "facet/islands.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "facet/image_io.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "support/golden.hpp"
#include "worlds/islands/kit.hpp"

namespace facet::test {
namespace {

// Building the world takes a few hundred milliseconds; the tests share one and copy it when
// they animate it.
const IslandsWorld& world() {
  static const IslandsWorld built = make_islands_world();
  return built;
}

struct Frame {
  Framebuffer framebuffer;
  FrameStats stats;
};

Frame render(const Scene& scene, int width, int height) {
  Camera camera = scene.camera;
  camera.aspect = static_cast<float>(width) / height;
  Renderer renderer;
  Frame frame{Framebuffer(width, height), {}};
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(frame.framebuffer);
  frame.stats = renderer.stats();
  return frame;
}

Frame render_at(double seconds, int width = 320, int height = 180) {
  IslandsWorld copy = world();
  copy.animate(seconds);
  return render(copy.scene, width, height);
}

TEST(Islands, BuildsWithItsMovingPartsAndIsRegistered) {
  const IslandsWorld& w = world();
  const int nodes = static_cast<int>(w.scene.nodes.size());
  for (int node :
       {w.flying_airplane, w.flying_propeller, w.parked_airplane, w.parked_propeller, w.boat}) {
    ASSERT_GE(node, 0);
    ASSERT_LT(node, nodes);
  }
  EXPECT_EQ(w.scene.nodes[w.flying_propeller].parent, w.flying_airplane);
  EXPECT_EQ(w.scene.nodes[w.parked_propeller].parent, w.parked_airplane);
  EXPECT_FALSE(w.clouds.empty());
  EXPECT_EQ(w.clouds.size(), w.cloud_origins.size());
  EXPECT_TRUE(w.scene.materials.at(w.waterfall_material).base_color_map);
  EXPECT_TRUE(w.scene.lighting.environment.show_as_background);
  EXPECT_NE(w.scene.lighting.fog.mode, FogMode::none);
  for (const auto& mesh : w.scene.meshes) EXPECT_NO_THROW(mesh->validate());

  const auto names = builtin_scene_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "islands"), names.end());
  EXPECT_EQ(make_builtin_scene("islands").triangle_count(), w.scene.triangle_count());
}

// At the size `make run` renders it. (Triangles covering no pixel centre are not drawn: at
// 1280 x 720, about 95,000 of the start view's triangles cover one.)
TEST(Islands, StartViewDrawsAtLeast100kTriangles) {
  EXPECT_GE(world().scene.triangle_count(), 100000u);
  const Frame frame = render(world().scene, 1920, 1080);
  EXPECT_GE(frame.stats.drawn, 100000u) << "of " << frame.stats.triangles_in << " in";
}

TEST(Islands, AnimationDependsOnTheTimeAlone) {
  const Frame first = render_at(12.5);
  // The same time reached after visiting another gives the same bytes.
  IslandsWorld revisited = world();
  revisited.animate(40.0);
  revisited.animate(12.5);
  EXPECT_EQ(render(revisited.scene, 320, 180).framebuffer.rgba8(), first.framebuffer.rgba8());
  EXPECT_EQ(render_at(12.5).framebuffer.rgba8(), first.framebuffer.rgba8());
  EXPECT_NE(render_at(14.0).framebuffer.rgba8(), first.framebuffer.rgba8());
}

TEST(Islands, BoatAndAirplaneMoveAndStayAboveTheWater) {
  IslandsWorld w = world();
  w.animate(0.0);
  const glm::vec3 boat_start = w.boat_position(), plane_start = w.airplane_position();
  const glm::vec3 hub = w.parked_propeller_position();
  float boat_travel = 0.0f, plane_travel = 0.0f;
  for (double t = 0.25; t <= 120.0; t += 0.25) {
    w.animate(t);
    const glm::vec3 boat = w.boat_position(), plane = w.airplane_position();
    ASSERT_GT(boat.y, 0.0f) << "the boat's deck went under at t = " << t;
    ASSERT_GT(plane.y, 80.0f) << "the airplane came down to the hills at t = " << t;
    boat_travel = std::max(boat_travel, glm::length(boat - boat_start));
    plane_travel = std::max(plane_travel, glm::length(plane - plane_start));
    // A spinning propeller stays on its airplane.
    ASSERT_LT(glm::length(w.parked_propeller_position() - hub), 1e-3f);
  }
  EXPECT_GT(boat_travel, 40.0f);    // across the strait
  EXPECT_GT(plane_travel, 300.0f);  // across the circle over both islands
}

TEST(Islands, PropellersAndWaterTurnAndFlow) {
  IslandsWorld w = world();
  w.animate(0.0);
  const glm::mat4 propeller = w.scene.nodes[w.parked_propeller].transform;
  const glm::mat3 falls = w.scene.materials[w.waterfall_material].base_color_map.transform;
  w.animate(0.31);
  EXPECT_NE(w.scene.nodes[w.parked_propeller].transform, propeller);
  EXPECT_NE(w.scene.materials[w.waterfall_material].base_color_map.transform, falls);
  // An hour in, time is still resolved finely: a tenth of a second still moves things.
  w.animate(3600.0);
  const glm::vec3 boat = w.boat_position();
  w.animate(3600.1);
  EXPECT_GT(glm::length(w.boat_position() - boat), 0.1f);
}

std::size_t triangles(const Scene& scene, const std::vector<MeshInstance>& instances) {
  std::size_t n = 0;
  for (const MeshInstance& instance : instances) {
    n += scene.meshes[instance.mesh]->primitive_count();
  }
  return n;
}

// The square in x and z of a ground chunk's node ("ground I,J"); none for other nodes.
struct ChunkSquare {
  float x0, z0, x1, z1;
};
std::optional<ChunkSquare> ground_chunk(const SceneNode& node) {
  int i = 0, j = 0;
  if (std::sscanf(node.name.c_str(), "ground %d,%d", &i, &j) != 2) return std::nullopt;
  const float chunk = islands::WorldBuilder::kChunk;
  return ChunkSquare{chunk * i, chunk * j, chunk * (i + 1), chunk * (j + 1)};
}

// Whether two coordinates are the same line of the chunk grid.
bool near(float a, float b) { return std::abs(a - b) < 1e-3f; }

// The ground's levels of detail (SceneNode::coarser) have the same points along their chunk's
// edges, so chunks drawn at different levels meet without cracks; and coarser levels have
// fewer triangles. (Points under the sea are left out: the ground hidden there is not drawn.)
TEST(Islands, GroundLevelsMeetAtTheChunkEdges) {
  const Scene& scene = world().scene;
  int ground_chunks = 0, with_levels = 0;
  for (const SceneNode& node : scene.nodes) {
    const std::optional<ChunkSquare> square = ground_chunk(node);
    if (!square) continue;
    ++ground_chunks;
    if (node.coarser.empty()) continue;
    ++with_levels;
    const auto [x0, z0, x1, z1] = *square;
    auto on_edge = [&](glm::vec3 p) {
      return p.y > 0.0f && (near(p.x, x0) || near(p.x, x1) || near(p.z, z0) || near(p.z, z1));
    };
    auto edge_points = [&](const std::vector<MeshInstance>& instances) {
      std::set<std::tuple<float, float, float>> points;
      for (const MeshInstance& instance : instances) {
        for (glm::vec3 p : scene.meshes[instance.mesh]->positions) {
          if (on_edge(p)) points.insert({p.x, p.y, p.z});
        }
      }
      return points;
    };
    const auto full = edge_points(node.instances);
    std::size_t finer = triangles(scene, node.instances);
    for (const DetailLevel& level : node.coarser) {
      ASSERT_EQ(edge_points(level.instances), full) << node.name << " from " << level.distance;
      const std::size_t n = triangles(scene, level.instances);
      if (finer > 8) {  // (a chunk all but under the sea may keep its few)
        EXPECT_LT(n, finer) << node.name << " from " << level.distance;
      }
      finer = n;
    }
  }
  EXPECT_GT(ground_chunks, 100);
  EXPECT_EQ(with_levels, ground_chunks);
}

// Where the beach line cuts the ground's triangles, the two triangles of an edge are cut at the
// same point: inside a chunk, at every level, every edge above the hidden sea floor belongs to
// exactly two triangles. (A cut on one side only would leave a vertex in the middle of the other
// triangle's edge, where pixels can fall through the ground.)
TEST(Islands, GroundEdgesInsideAChunkJoinTwoTriangles) {
  const Scene& scene = world().scene;
  using Point = std::tuple<float, float, float>;  // ordered, for the map's keys
  auto point = [](glm::vec3 p) { return Point{p.x, p.y, p.z}; };
  int checked = 0, unjoined = 0;
  for (const SceneNode& node : scene.nodes) {
    const std::optional<ChunkSquare> square = ground_chunk(node);
    if (!square) continue;
    const auto [x0, z0, x1, z1] = *square;
    auto on_border = [&](glm::vec3 a, glm::vec3 b) {
      return (near(a.x, x0) && near(b.x, x0)) || (near(a.x, x1) && near(b.x, x1)) ||
             (near(a.z, z0) && near(b.z, z0)) || (near(a.z, z1) && near(b.z, z1));
    };
    std::vector<const std::vector<MeshInstance>*> levels = {&node.instances};
    for (const DetailLevel& level : node.coarser) levels.push_back(&level.instances);
    for (const std::vector<MeshInstance>* instances : levels) {
      std::map<std::pair<Point, Point>, int> edges;  // by their ends, lower first
      for (const MeshInstance& instance : *instances) {
        const Mesh& mesh = *scene.meshes[instance.mesh];
        const std::size_t corners =
            mesh.indices.empty() ? mesh.positions.size() : mesh.indices.size();
        auto corner = [&](std::size_t k) {
          return mesh.positions[mesh.indices.empty() ? k : mesh.indices[k]];
        };
        for (std::size_t t = 0; t + 2 < corners; t += 3) {
          const glm::vec3 p[3] = {corner(t), corner(t + 1), corner(t + 2)};
          if (glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) == 0.0f) continue;  // no pixels
          for (int e = 0; e < 3; ++e) {
            ++edges[std::minmax(point(p[e]), point(p[(e + 1) % 3]))];
          }
        }
      }
      for (const auto& [ends, count] : edges) {
        const glm::vec3 a = std::make_from_tuple<glm::vec3>(ends.first);
        const glm::vec3 b = std::make_from_tuple<glm::vec3>(ends.second);
        if (on_border(a, b) || std::max(a.y, b.y) < -0.02f) continue;
        ++checked;
        if (count != 2 && ++unjoined <= 5) {
          ADD_FAILURE() << node.name << ": the edge (" << a.x << ", " << a.y << ", " << a.z
                        << ") - (" << b.x << ", " << b.y << ", " << b.z << ") joins " << count
                        << " triangles";
        }
      }
    }
  }
  EXPECT_EQ(unjoined, 0);
  EXPECT_GT(checked, 100000);
}

// Trees, bushes and stones have stand-ins for afar with fewer triangles.
TEST(Islands, FarSceneryHasFewerTriangles) {
  const Scene& scene = world().scene;
  int with_levels = 0;
  for (const SceneNode& node : scene.nodes) {
    if (node.name.rfind("scenery ", 0) != 0 || node.coarser.empty()) continue;
    ++with_levels;
    ASSERT_EQ(node.coarser.size(), 1u);
    EXPECT_LT(triangles(scene, node.coarser[0].instances), triangles(scene, node.instances))
        << node.name;
  }
  EXPECT_GT(with_levels, 100);
}

TEST(Islands, StartViewMatchesGolden) {
  const Frame frame = render(world().scene, 320, 180);
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / "islands_default.png").string();
  write_image(frame.framebuffer, path);
  expect_matches_golden(path, "islands_default");
}

}  // namespace
}  // namespace facet::test
