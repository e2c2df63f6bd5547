// The world-builder kit of the islands world: the surfaces things are made of, a Model (one mesh
// per surface, composed from procedural shapes placed by transforms), and the WorldBuilder that
// turns models into Scene nodes — static scenery merged into one draw per surface, moving parts
// as their own nodes.
#pragma once

#include <array>
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "facet/mesh.hpp"
#include "facet/scene.hpp"
#include "worlds/islands/textures.hpp"

namespace facet::islands {

// What a part is made of; each surface is one material of the world (material index = the
// enum's value), so all grass in the world is one draw.
enum class Surface {
  grass,
  sand,
  rock,
  ocean,
  river,
  falls,
  foam,
  wood,
  bark,
  brick,
  roof,
  runway,
  threshold,
  concrete,
  metal,
  paint,  // plain white, colored by the tint
  glass,
  foliage,
  palm,  // foliage drawn from both sides: the fronds are single quads
  cloud,
  count
};
inline constexpr std::size_t kSurfaceCount = static_cast<std::size_t>(Surface::count);

// --- placing things: read "at(p) * rot_y(30) * scale(s)" right to left --------------------------

glm::mat4 at(glm::vec3 position, float yaw_degrees = 0.0f);  // move there, turned about +Y
glm::mat4 rot_x(float degrees);
glm::mat4 rot_y(float degrees);
glm::mat4 rot_z(float degrees);
glm::mat4 scale(glm::vec3 factors);

// A vertex color from sRGB components (colors are picked by eye, in sRGB).
glm::vec4 srgb(float r, float g, float b);

// The mesh without the triangles that face `direction` (within a degree): the caps of a trunk
// hidden in the ground or in the next segment, which would only cost time.
Mesh without_faces_toward(Mesh mesh, glm::vec3 direction);

// A thing under construction, in its own space: one triangle mesh per surface it uses.
class Model {
 public:
  // Adds `shape` made of `surface`, placed by `place` and tinted by `tint`. Texture
  // coordinates are projected from the placed positions (so a texture has the same scale on
  // every part) unless the surface keeps the shape's own (bark, foliage, water, runway).
  Model& add(Surface surface, Mesh shape, const glm::mat4& place = glm::mat4(1.0f),
             glm::vec4 tint = glm::vec4(1.0f));
  // As add(), but always keeps the shape's texture coordinates.
  Model& add_keeping_uv(Surface surface, Mesh shape, const glm::mat4& place = glm::mat4(1.0f),
                        glm::vec4 tint = glm::vec4(1.0f));
  // Adds every part of `other`, placed by `place`.
  Model& add(const Model& other, const glm::mat4& place = glm::mat4(1.0f));

  const Mesh& mesh(Surface surface) const { return meshes_[static_cast<std::size_t>(surface)]; }
  std::size_t triangle_count() const;

 private:
  std::array<Mesh, kSurfaceCount> meshes_;
};

// Static scenery is merged per surface within square chunks of the map, so the renderer skips
// the chunks out of view whole (its draw culling) while each still draws in few calls.
// Scenery is drawn in three layers: what stands on the ground, then the ground, then what lies
// under both (the sea). The depth test then skips the ground and the sea behind the things in
// front of them, instead of shading them first and covering them later.
class WorldBuilder {
 public:
  // Metres; a multiple of every terrain cell size. Chunks of 20 m rather than 60 m leave more of
  // the land's vertices out of view at the start camera.
  static constexpr float kChunk = 20.0f;
  // Where scenery placed with a `far` stand-in switches to it (SceneNode::coarser: metres from
  // the chunk at a 60 degree field of view). That far, a tree is a few dozen pixels at 720p.
  // Nearer, the start view would draw fewer than the 100,000 triangles at 1080p that the issue
  // asks for (world.cpp).
  static constexpr float kFarSceneryFrom = 180.0f;

  explicit WorldBuilder(const IslandTextures& textures);

  // Static scenery: `model` placed by `where`, merged into the chunk of where's origin; `far`,
  // if given, stands in for it from kFarSceneryFrom on.
  void place(const Model& model, const glm::mat4& where = glm::mat4(1.0f));
  void place(const Model& model, const Model& far, const glm::mat4& where);
  // Static scenery already in world space, merged into the chunk holding `anchor` (x, z).
  void place_in_chunk(const Model& model, glm::vec2 anchor);
  // The ground of the chunk holding `anchor` (x, z), already in world space, drawn after the
  // scenery: levels[0] near, levels[k] from distances[k - 1] on.
  void place_ground(std::vector<Model> levels, std::span<const float> distances, glm::vec2 anchor);
  // Static scenery drawn after everything else, such as the sea around the islands.
  void place_last(const Model& model);
  // A part that moves: its own node (under `parent`, or a root), one instance per surface.
  int add_node(const std::string& name, const Model& model, const glm::mat4& where,
               int parent = -1);
  static int material(Surface surface) { return static_cast<int>(surface); }

  // Adds the merged scenery, one node per chunk and layer, and hands over the scene.
  Scene finish();
  Scene& scene() { return scene_; }

 private:
  using ChunkKey = std::pair<int, int>;
  // A chunk's things at levels of detail: levels[0] near, levels[k] from distances[k - 1] on.
  struct Chunk {
    std::vector<Model> levels;
    std::vector<float> distances;
    bool coarser_differ = false;  // else only levels[0] is drawn
  };
  using Chunks = std::map<ChunkKey, Chunk>;  // ordered: the same scene every time
  static ChunkKey chunk_key(glm::vec2 anchor);
  Chunk& scenery_chunk(glm::vec2 anchor);
  // One mesh per surface the model uses, added to the scene.
  std::vector<MeshInstance> add_meshes(const Model& model);
  void add_chunks(const std::string& layer, Chunks& chunks);

  Scene scene_;
  Chunks scenery_, ground_;
  Model last_;
};

}  // namespace facet::islands
