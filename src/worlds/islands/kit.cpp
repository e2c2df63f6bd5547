// The world-builder kit (see kit.hpp): transforms, Model composition and the surface materials.
#include "worlds/islands/kit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>
#include <vector>

#include "facet/error.hpp"
#include "facet/procedural.hpp"

namespace facet::islands {
namespace {

// Metres per texture repeat when a surface's texture coordinates are projected; 0 keeps the
// shape's own coordinates (bark wraps around a trunk, a runway's paint runs along it).
constexpr float kTile[kSurfaceCount] = {
    6.0f,  // grass
    5.0f,  // sand
    8.0f,  // rock
    0.0f,  // ocean
    0.0f,  // river
    0.0f,  // falls
    0.0f,  // foam
    1.5f,  // wood
    0.0f,  // bark
    2.0f,  // brick
    2.5f,  // roof
    0.0f,  // runway
    0.0f,  // threshold
    8.0f,  // concrete
    3.0f,  // metal
    0.0f,  // paint
    0.0f,  // glass
    0.0f,  // foliage
    0.0f,  // palm
    0.0f,  // cloud
};

// Box projection: each vertex takes the plane its normal faces most, so walls get upright
// bricks and floors get the texture seen from above.
void project_uv(Mesh& mesh, float tile) {
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i] / tile, n = glm::abs(mesh.normals[i]);
    if (n.y >= n.x && n.y >= n.z) {
      mesh.texcoords[i] = {p.x, -p.z};
    } else if (n.x >= n.z) {
      mesh.texcoords[i] = {p.z, p.y};
    } else {
      mesh.texcoords[i] = {p.x, p.y};
    }
  }
}

Material textured(const char* name, const TexturePtr& texture,
                  ShadingModel shading = ShadingModel::lambert) {
  Material m;
  m.name = name;
  m.shading = shading;
  m.base_color_map.texture = texture;
  return m;
}

Material shiny(Material m, float specular, float shininess) {
  m.shading = ShadingModel::blinn_phong;
  m.specular_color = glm::vec3(specular);
  m.shininess = shininess;
  return m;
}

Material plain(const char* name, glm::vec3 emissive = glm::vec3(0.0f)) {
  Material m;
  m.name = name;
  m.emissive = emissive;
  return m;
}

// One material per surface, in the order of the Surface enum.
std::array<Material, kSurfaceCount> surface_materials(const IslandTextures& t) {
  Material palm = textured("palm", t.foliage);
  palm.cull = CullMode::none;  // single-sided fronds, seen from above and below
  // Water is opaque and nothing is seen beneath it: as a caster it could only shade the shores,
  // where their slopes met it in the shadow maps.
  Material ocean = shiny(textured("ocean", t.water), 0.45f, 64.0f);
  ocean.reflects_scene = true;  // the islands and the sky mirrored in the sea
  ocean.reflectivity = 0.5f;
  ocean.casts_shadows = false;
  Material river = shiny(textured("river", t.water), 0.35f, 48.0f);
  river.casts_shadows = false;
  Material glass = shiny(plain("glass"), 0.9f, 96.0f);
  glass.base_color = {0.05f, 0.08f, 0.12f, 1.0f};
  return {
      textured("grass", t.grass),
      textured("sand", t.sand),
      textured("rock", t.rock),
      ocean,
      river,
      textured("falls", t.falls),
      plain("foam", glm::vec3(0.25f)),
      textured("wood", t.wood),
      textured("bark", t.bark),
      textured("brick", t.brick),
      textured("roof", t.roof),
      textured("runway", t.runway),
      textured("threshold", t.threshold),
      textured("concrete", t.concrete),
      shiny(textured("metal", t.metal), 0.5f, 48.0f),
      shiny(plain("paint"), 0.25f, 32.0f),
      glass,
      textured("foliage", t.foliage),
      palm,
      plain("cloud", glm::vec3(0.3f, 0.3f, 0.32f)),
  };
}

}  // namespace

glm::mat4 at(glm::vec3 position, float yaw_degrees) {
  return glm::translate(glm::mat4(1.0f), position) * rot_y(yaw_degrees);
}
glm::mat4 rot_x(float degrees) {
  return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), {1, 0, 0});
}
glm::mat4 rot_y(float degrees) {
  return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), {0, 1, 0});
}
glm::mat4 rot_z(float degrees) {
  return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), {0, 0, 1});
}
glm::mat4 scale(glm::vec3 factors) { return glm::scale(glm::mat4(1.0f), factors); }

glm::vec4 srgb(float r, float g, float b) {
  auto linear = [](float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  };
  return {linear(r), linear(g), linear(b), 1.0f};
}

Mesh without_faces_toward(Mesh mesh, glm::vec3 direction) {
  const glm::vec3 d = glm::normalize(direction);
  std::vector<std::uint32_t> kept;
  kept.reserve(mesh.indices.size());
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]],
                    c = mesh.positions[mesh.indices[i + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    if (length > 0.0f && glm::dot(n, d) > 0.99985f * length) continue;  // cos(1 degree)
    kept.insert(kept.end(), {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]});
  }
  mesh.indices = std::move(kept);
  return mesh;
}

Model& Model::add(Surface surface, Mesh shape, const glm::mat4& place, glm::vec4 tint) {
  const float tile = kTile[static_cast<std::size_t>(surface)];
  Mesh placed = transformed(std::move(shape), place);
  if (tile > 0.0f) project_uv(placed, tile);
  return add_keeping_uv(surface, std::move(placed), glm::mat4(1.0f), tint);
}

Model& Model::add_keeping_uv(Surface surface, Mesh shape, const glm::mat4& place, glm::vec4 tint) {
  Mesh placed = place == glm::mat4(1.0f) ? std::move(shape) : transformed(std::move(shape), place);
  // Every part carries colors, so merged meshes never mix colored and uncolored vertices.
  if (placed.colors.empty()) placed.colors.assign(placed.positions.size(), tint);
  append(meshes_[static_cast<std::size_t>(surface)], placed);
  return *this;
}

Model& Model::add(const Model& other, const glm::mat4& place) {
  for (std::size_t s = 0; s < kSurfaceCount; ++s) {
    if (other.meshes_[s].positions.empty()) continue;
    append(meshes_[s],
           place == glm::mat4(1.0f) ? other.meshes_[s] : transformed(other.meshes_[s], place));
  }
  return *this;
}

std::size_t Model::triangle_count() const {
  std::size_t count = 0;
  for (const Mesh& mesh : meshes_) count += mesh.primitive_count();
  return count;
}

WorldBuilder::WorldBuilder(const IslandTextures& textures) {
  for (Material& m : surface_materials(textures)) scene_.materials.push_back(std::move(m));
  for (const TexturePtr& t :
       {textures.grass, textures.sand, textures.rock, textures.water, textures.falls, textures.wood,
        textures.bark, textures.brick, textures.roof, textures.runway, textures.threshold,
        textures.concrete, textures.metal, textures.foliage}) {
    scene_.textures.push_back(t);
  }
}

void WorldBuilder::place(const Model& model, const glm::mat4& where) {
  place_in_chunk(Model{}.add(model, where), {where[3].x, where[3].z});
}

void WorldBuilder::place(const Model& model, const Model& far, const glm::mat4& where) {
  Chunk& chunk = scenery_chunk({where[3].x, where[3].z});
  chunk.levels[0].add(model, where);
  chunk.levels[1].add(far, where);
  chunk.coarser_differ = true;
}

WorldBuilder::ChunkKey WorldBuilder::chunk_key(glm::vec2 anchor) {
  return {static_cast<int>(std::floor(anchor.x / kChunk)),
          static_cast<int>(std::floor(anchor.y / kChunk))};
}

WorldBuilder::Chunk& WorldBuilder::scenery_chunk(glm::vec2 anchor) {
  Chunk& chunk = scenery_[chunk_key(anchor)];
  if (chunk.levels.empty()) {  // near, and afar (the near things where they have no stand-in)
    chunk.levels.resize(2);
    chunk.distances = {kFarSceneryFrom};
  }
  return chunk;
}

void WorldBuilder::place_in_chunk(const Model& model, glm::vec2 anchor) {
  for (Model& level : scenery_chunk(anchor).levels) level.add(model);
}

void WorldBuilder::place_ground(std::vector<Model> levels, std::span<const float> distances,
                                glm::vec2 anchor) {
  if (levels.size() != distances.size() + 1) {
    throw Error("world builder: ground levels need one distance each past the first");
  }
  Chunk& chunk = ground_[chunk_key(anchor)];
  chunk.coarser_differ = levels.size() > 1;
  if (chunk.levels.empty()) {
    chunk.levels = std::move(levels);
    chunk.distances.assign(distances.begin(), distances.end());
    return;
  }
  if (!std::equal(distances.begin(), distances.end(), chunk.distances.begin(),
                  chunk.distances.end())) {
    throw Error("world builder: ground placed in one chunk at different levels of detail");
  }
  for (std::size_t k = 0; k < levels.size(); ++k) chunk.levels[k].add(levels[k]);
}

void WorldBuilder::place_last(const Model& model) { last_.add(model); }

std::vector<MeshInstance> WorldBuilder::add_meshes(const Model& model) {
  std::vector<MeshInstance> instances;
  for (std::size_t s = 0; s < kSurfaceCount; ++s) {
    const Mesh& mesh = model.mesh(static_cast<Surface>(s));
    if (mesh.positions.empty()) continue;
    scene_.meshes.push_back(std::make_shared<const Mesh>(mesh));
    instances.push_back({static_cast<int>(scene_.meshes.size()) - 1, static_cast<int>(s)});
  }
  return instances;
}

int WorldBuilder::add_node(const std::string& name, const Model& model, const glm::mat4& where,
                           int parent) {
  SceneNode node;
  node.name = name;
  node.transform = where;
  node.parent = parent;
  node.instances = add_meshes(model);
  scene_.nodes.push_back(std::move(node));
  return static_cast<int>(scene_.nodes.size()) - 1;
}

void WorldBuilder::add_chunks(const std::string& layer, Chunks& chunks) {
  for (const auto& [key, chunk] : chunks) {
    if (chunk.levels[0].triangle_count() == 0) continue;  // open sea
    SceneNode node;
    node.name = layer + " " + std::to_string(key.first) + "," + std::to_string(key.second);
    node.instances = add_meshes(chunk.levels[0]);
    for (std::size_t k = 1; chunk.coarser_differ && k < chunk.levels.size(); ++k) {
      node.coarser.push_back({chunk.distances[k - 1], add_meshes(chunk.levels[k])});
    }
    scene_.nodes.push_back(std::move(node));
  }
  chunks.clear();
}

Scene WorldBuilder::finish() {
  add_chunks("scenery", scenery_);
  add_chunks("ground", ground_);
  if (last_.triangle_count() != 0) add_node("sea", last_, glm::mat4(1.0f));
  last_ = Model{};
  scene_.bound_detail_levels();
  return std::move(scene_);
}

}  // namespace facet::islands
