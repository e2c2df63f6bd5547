// Every model format assimp reads, converted to a facet Scene: meshes, the node hierarchy,
// cameras and punctual lights (materials and textures: import_materials.cpp). Runs once per
// model at load time; the renderer only ever sees the Scene.
//
// assimp post-processing is limited to what keeps the file's meaning: triangulate, split
// meshes by primitive type, validate, drop invalid data. They run after the file is read rather
// than inside ReadFile (whose only difference is that validation would come before assimp's
// scene preprocessor): point clouds (vertices without faces, as assimp's PLY and OBJ readers give
// them) get one point face per finite vertex in between, since validation rejects a mesh
// without faces (add_point_faces). Identical vertices are joined by facet
// (finish_mesh), and so are normals generated (compute_smooth_normals, with the crease angle).
// No pre-transforming (the node hierarchy is kept), no rescaling or re-centring.
#include "import/import_assimp.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "facet/error.hpp"
#include "facet/mesh_tools.hpp"
#include "import/assimp_fence.hpp"
#include "import/assimp_read_report.hpp"
#include "import/guarded_io.hpp"

namespace facet::io {

namespace {

// No aiProcess_JoinIdenticalVertices: finish_mesh joins them itself, exactly (bit for bit)
// and much faster than assimp's step.
constexpr unsigned kPostProcess = aiProcess_Triangulate | aiProcess_SortByPType |
                                  aiProcess_ValidateDataStructure | aiProcess_FindInvalidData;

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? "unknown error" : text;
}

bool is_gltf(const std::string& path, const aiScene& ai) {
  const std::string extension = lower_case(std::filesystem::path(path).extension().string());
  if (extension == ".gltf" || extension == ".glb") return true;
  for (unsigned i = 0; ai.mMaterials && i < ai.mNumMaterials; ++i) {
    aiString mode;
    if (ai.mMaterials[i] && ai.mMaterials[i]->Get("$mat.gltf.alphaMode", 0, 0, mode) == AI_SUCCESS)
      return true;
  }
  return false;
}

float srgb_to_linear(float c) {
  c = std::max(c, 0.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
glm::vec3 to_vec3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

// assimp's PLY reader (a file without a face element) and OBJ reader (`v` lines only) hand back
// a point cloud as a mesh of vertices without faces, which validation rejects ("contains no
// faces"): give such a mesh one point face per vertex, as the glTF reader does for POINTS.
// Vertices whose position is not finite get none (scanners write NaN for a missing sample):
// post-processing ignores vertices no face uses, where one NaN among them would make it drop
// the whole mesh, and convert_mesh keeps only the points faces use. Returns how many were left
// out.
std::size_t add_point_faces(aiScene& ai) {
  std::size_t dropped = 0;
  for (unsigned i = 0; ai.mMeshes && i < ai.mNumMeshes; ++i) {
    aiMesh* mesh = ai.mMeshes[i];
    if (!mesh || mesh->mFaces || mesh->mNumFaces != 0 || !mesh->mVertices) continue;
    const unsigned n = mesh->mNumVertices;
    unsigned finite_count = 0;
    for (unsigned v = 0; v < n; ++v) finite_count += finite(to_vec3(mesh->mVertices[v]));
    dropped += n - finite_count;
    if (finite_count == 0) continue;
    mesh->mFaces = new aiFace[finite_count];  // assimp frees them with the scene
    mesh->mNumFaces = finite_count;
    for (unsigned v = 0, f = 0; v < n; ++v) {
      if (!finite(to_vec3(mesh->mVertices[v]))) continue;
      mesh->mFaces[f].mNumIndices = 1;
      mesh->mFaces[f++].mIndices = new unsigned[1]{v};
    }
    mesh->mPrimitiveTypes = aiPrimitiveType_POINT;
  }
  return dropped;
}

// The attributes of one aiMesh. With SortByPType each aiMesh holds one primitive type: a
// triangle, line or point mesh.
std::optional<Mesh> convert_mesh(const aiMesh& in, bool linear_colors) {
  std::size_t triangles = 0, lines = 0, points = 0;
  if (!in.mFaces) return std::nullopt;  // assimp can hand back partial scenes
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    if (!in.mFaces[f].mIndices) continue;
    triangles += in.mFaces[f].mNumIndices == 3;
    lines += in.mFaces[f].mNumIndices == 2;
    points += in.mFaces[f].mNumIndices == 1;
  }
  if (!in.mVertices || (triangles == 0 && lines == 0 && points == 0)) return std::nullopt;
  Mesh mesh;
  mesh.topology = triangles > 0 ? Topology::triangles
                  : lines > 0   ? Topology::lines
                                : Topology::points;
  const unsigned corners = triangles > 0 ? 3 : lines > 0 ? 2 : 1;
  const unsigned n = in.mNumVertices;
  mesh.positions.resize(n);
  for (unsigned i = 0; i < n; ++i)
    mesh.positions[i] = {in.mVertices[i].x, in.mVertices[i].y, in.mVertices[i].z};
  if (in.mNormals) {
    mesh.normals.resize(n);
    for (unsigned i = 0; i < n; ++i)
      mesh.normals[i] = {in.mNormals[i].x, in.mNormals[i].y, in.mNormals[i].z};
  }
  if (in.mTextureCoords[0]) {
    mesh.texcoords.resize(n);
    for (unsigned i = 0; i < n; ++i)
      mesh.texcoords[i] = {in.mTextureCoords[0][i].x, in.mTextureCoords[0][i].y};
  }
  if (in.mColors[0]) {
    mesh.colors.resize(n);
    for (unsigned i = 0; i < n; ++i) {
      const aiColor4D& c = in.mColors[0][i];
      // glTF vertex colors are linear by definition; PLY/OBJ/... colors are display (sRGB)
      // values, as Blender reads them.
      mesh.colors[i] = linear_colors ? glm::vec4(c.r, c.g, c.b, c.a)
                                     : glm::vec4(srgb_to_linear(c.r), srgb_to_linear(c.g),
                                                 srgb_to_linear(c.b), c.a);
    }
  }
  if (in.mTangents && in.mBitangents && in.mNormals) {
    mesh.tangents.resize(n);
    for (unsigned i = 0; i < n; ++i) {
      glm::vec3 t(in.mTangents[i].x, in.mTangents[i].y, in.mTangents[i].z);
      glm::vec3 b(in.mBitangents[i].x, in.mBitangents[i].y, in.mBitangents[i].z);
      float w = glm::dot(glm::cross(mesh.normals[i], t), b) < 0.0f ? -1.0f : 1.0f;
      mesh.tangents[i] = glm::vec4(t, w);
    }
  }
  mesh.indices.reserve(static_cast<std::size_t>(corners) * std::max({triangles, lines, points}));
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (!face.mIndices || face.mNumIndices != corners) continue;
    mesh.indices.insert(mesh.indices.end(), face.mIndices, face.mIndices + corners);
  }
  // A point mesh as the points its indices name, in their order, without indices: the vertices
  // no point uses (add_point_faces left out the non-finite ones) are gone.
  if (mesh.topology == Topology::points) expand_indices(mesh);
  return mesh;
}

glm::mat4 to_glm(const aiMatrix4x4& m) {
  // aiMatrix4x4 is row-major (a1 a2 a3 a4 is the first row); glm is column-major.
  glm::mat4 out;
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) out[column][row] = m[row][column];
  }
  return out;
}

struct NodeBuilder {
  const aiScene& ai;
  const std::vector<int>& mesh_index;  // aiMesh -> Scene::meshes, -1 if dropped
  const std::vector<int>& mesh_material;
  Scene& scene;
  std::unordered_map<std::string, int> by_name;

  // Depth first, parents before children (SceneNode::parent must come first). A stack rather
  // than recursion, so a very deep hierarchy cannot overflow the call stack.
  void build() {
    struct Pending {
      const aiNode* node;
      int parent;
    };
    std::vector<Pending> stack;
    if (ai.mRootNode) stack.push_back({ai.mRootNode, -1});
    std::unordered_map<const aiNode*, bool> seen;  // assimp validates, but never loop forever
    while (!stack.empty()) {
      Pending next = stack.back();
      stack.pop_back();
      if (!next.node || !seen.emplace(next.node, true).second) continue;
      const int index = add(*next.node, next.parent);
      for (unsigned c = next.node->mChildren ? next.node->mNumChildren : 0; c-- > 0;) {
        stack.push_back({next.node->mChildren[c], index});
      }
    }
  }

  int add(const aiNode& node, int parent) {
    SceneNode out;
    out.name = node.mName.C_Str();
    out.transform = to_glm(node.mTransformation);
    out.parent = parent;
    for (unsigned i = 0; node.mMeshes && i < node.mNumMeshes; ++i) {
      const unsigned m = node.mMeshes[i];
      if (m < mesh_index.size() && mesh_index[m] >= 0) {
        out.instances.push_back({mesh_index[m], mesh_material[m]});
      }
    }
    scene.nodes.push_back(std::move(out));
    const int index = static_cast<int>(scene.nodes.size()) - 1;
    by_name.try_emplace(scene.nodes.back().name, index);
    return index;
  }
};

void import_meshes(const aiScene& ai, bool gltf, const std::string& path,
                   const ImportOptions& options, Scene& scene, std::vector<int>& mesh_index,
                   std::vector<int>& mesh_material) {
  mesh_index.assign(ai.mNumMeshes, -1);
  mesh_material.assign(ai.mNumMeshes, 0);
  for (unsigned i = 0; ai.mMeshes && i < ai.mNumMeshes; ++i) {
    if (!ai.mMeshes[i]) continue;
    std::optional<Mesh> mesh = convert_mesh(*ai.mMeshes[i], gltf);
    if (!mesh) continue;
    const unsigned material = ai.mMeshes[i]->mMaterialIndex;
    mesh_material[i] = material < scene.materials.size() ? static_cast<int>(material) : 0;
    finish_mesh(*mesh, scene.materials[mesh_material[i]], options,
                path + ": mesh " + std::to_string(i));
    scene.meshes.push_back(std::make_shared<const Mesh>(std::move(*mesh)));
    mesh_index[i] = static_cast<int>(scene.meshes.size()) - 1;
  }
}

// Every texture some material uses, once.
void collect_textures(Scene& scene) {
  for (const Material& m : scene.materials) {
    for (const TextureMap* map : {&m.base_color_map, &m.normal_map, &m.specular_map,
                                  &m.metallic_roughness_map, &m.occlusion_map, &m.emissive_map}) {
      if (map->texture && std::find(scene.textures.begin(), scene.textures.end(), map->texture) ==
                              scene.textures.end()) {
        scene.textures.push_back(map->texture);
      }
    }
  }
}

Scene convert(const aiScene& ai, const std::string& path, const ImportOptions& options) {
  const bool gltf = is_gltf(path, ai);
  Scene scene;
  TextureLoader textures(ai, path, options);
  scene.materials = import_materials(ai, gltf, textures);
  collect_textures(scene);
  std::vector<int> mesh_index, mesh_material;
  import_meshes(ai, gltf, path, options, scene, mesh_index, mesh_material);
  NodeBuilder nodes{ai, mesh_index, mesh_material, scene, {}};
  nodes.build();
  import_cameras_and_lights(ai, gltf, path, options, nodes.by_name, scene);
  return scene;
}

// assimp's read of the file and the post-processing after it, as the fenced child and the read
// in this process both make it (read, then post-process, validation first: point clouds need their
// faces in between). The importer's scene, or null (importer.GetErrorString() says why); `dropped`:
// the points with a non-finite position left out.
const aiScene* read_and_process(Assimp::Importer& importer, const std::string& path,
                                std::size_t& dropped) {
  const aiScene* ai = importer.ReadFile(path, 0);
  if (!ai) return nullptr;
  dropped = add_point_faces(*const_cast<aiScene*>(ai));  // the importer's own scene, not const
  return importer.ApplyPostProcessing(kPostProcess);
}

// What the dump leaves out (AssimpReadReport), taken from the scene read.
void note_left_out(const aiScene& ai, AssimpReadReport& report) {
  for (unsigned i = 0; ai.mTextures && i < ai.mNumTextures; ++i) {
    report.texture_names.emplace_back(ai.mTextures[i] ? ai.mTextures[i]->mFilename.C_Str() : "");
  }
  for (unsigned i = 0; ai.mCameras && i < ai.mNumCameras; ++i) {
    report.orthographic_widths.push_back(ai.mCameras[i] ? ai.mCameras[i]->mOrthographicWidth
                                                        : 0.0f);
  }
}

// ... and put back into the scene read from the dump; false when the scene does not have as
// many textures and cameras.
bool restore_left_out(const AssimpReadReport& report, aiScene& ai) {
  const unsigned textures = ai.mTextures ? ai.mNumTextures : 0;
  const unsigned cameras = ai.mCameras ? ai.mNumCameras : 0;
  if (report.texture_names.size() != textures || report.orthographic_widths.size() != cameras) {
    return false;
  }
  for (unsigned i = 0; i < textures; ++i) {
    if (ai.mTextures[i]) ai.mTextures[i]->mFilename.Set(report.texture_names[i]);
  }
  for (unsigned i = 0; i < cameras; ++i) {
    if (ai.mCameras[i]) ai.mCameras[i]->mOrthographicWidth = report.orthographic_widths[i];
  }
  return true;
}

// convert(), its errors (bad_alloc on absurd sizes, and the like) as facet::Error.
Scene convert_or_throw(const aiScene& ai, const std::string& path, const ImportOptions& options) {
  try {
    return convert(ai, path, options);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path + ": cannot import: " + one_line(e.what()));
  }
}

// assimp's read of the file (read_and_process) with every file it opens held to facet's rules:
// the scene, or null when the read failed; `report` gets the error, the refusals and the points
// left out. The same read in the fenced child and, unfenced, here.
const aiScene* read_reporting(Assimp::Importer& importer, const std::string& path,
                              const ReferenceRules& rules, AssimpReadReport& report) {
  auto* files = new GuardedIOSystem(rules);  // the importer owns it
  importer.SetIOHandler(files);
  std::size_t dropped = 0;
  const aiScene* ai = nullptr;
  try {
    ai = read_and_process(importer, path, dropped);
    if (!ai) report.error = importer.GetErrorString();
  } catch (const std::exception& e) {  // assimp's DeadlyImportError escapes in some readers
    report.error = e.what();
  }
  if (!ai && report.error.empty()) report.error = "unknown error";
  report.refusals = files->refusals();
  report.dropped_points = dropped;
  return ai;
}

// The import's end, from a read and its report: the points left out warned of; a failed read
// as one facet::Error (a file assimp needed and was refused makes the failure: that rather than
// assimp's guess at why the file it could not open is missing); else the refusals warned of
// (the import went on without them: an OBJ's material library) and the scene converted.
Scene finish_import(const AssimpReadReport& report, const aiScene* ai, const std::string& path,
                    const ImportOptions& options) {
  if (report.dropped_points > 0) {
    io::warn(options, path + ": " + std::to_string(report.dropped_points) +
                          " points with a non-finite position left out");
  }
  if (!ai) {
    throw Error(report.refusals.empty() ? path + ": cannot import: " + one_line(report.error)
                                        : report.refusals.front());
  }
  for (const std::string& refusal : report.refusals) io::warn(options, refusal);
  return convert_or_throw(*ai, path, options);
}

// The fenced child's read (assimp_fence.hpp): assimp reads the file there, and what it made
// goes to `out` as assimp's binary dump, with the read's report. Allocations past the child's
// limit while reading end it (the fence's error); past it while dumping, nothing is sent, and
// the caller reads the file itself.
void read_in_child(const std::string& path, const ReferenceRules& rules, int out) {
  Assimp::Importer importer;
  AssimpReadReport report;
  const aiScene* ai = read_reporting(importer, path, rules, report);
  // assimp reports an allocation that failed (under the child's memory limit) as an ordinary
  // read error: the fence must hear of it, or the caller's read makes it without a limit.
  if (!ai && report.error.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
  if (!ai) {
    (void)write_read_report(out, report);  // unless it failed: then the caller reads the file
    return;
  }
  std::set_new_handler(nullptr);
  try {
    Assimp::Exporter exporter;
    const aiExportDataBlob* blob = exporter.ExportToBlob(ai, "assbin");
    if (!blob || !blob->data) return;
    // The caller reads the dump with assimp in its own process: read here first, under the
    // child's limits, it is known to end there too.
    Assimp::Importer check;
    if (!check.ReadFileFromMemory(blob->data, blob->size, 0, "assbin")) return;
    report.dump = {static_cast<const char*>(blob->data), blob->size};
    note_left_out(*ai, report);
    (void)write_read_report(out, report);
  } catch (const std::exception&) {  // out of memory, or the exporter's own errors
  }
}

}  // namespace

Scene import_assimp_scene(const std::string& path, const ImportOptions& options) {
  precheck_model(path);
  const ReferenceRules rules(path, options);
  // assimp reads the file in a child process (assimp_fence.hpp): a hang or crash inside it is
  // an error here, not this process's end.
  FencedResult fenced =
      run_fenced(path, options, [&](int out) { read_in_child(path, rules, out); });
  if (const std::optional<AssimpReadReport> report = parse_read_report(fenced.bytes())) {
    if (!report->error.empty()) return finish_import(*report, nullptr, path, options);
    Assimp::Importer importer;
    const aiScene* ai =
        importer.ReadFileFromMemory(report->dump.data(), report->dump.size(), 0, "assbin");
    fenced = FencedResult();  // the dump is read: its memory goes (report->dump with it)
    if (ai && restore_left_out(*report, *const_cast<aiScene*>(ai))) {
      return finish_import(*report, ai, path, options);
    }
  }
  if (options.fence_assimp) {
    io::warn(options, path +
                          ": the fenced read sent no scene back (assimp could not dump it within "
                          "ImportOptions::import_memory_limit_bytes): read in this process");
  }
  // Unfenced (ImportOptions::fence_assimp), or the child sent no whole report: the read here.
  Assimp::Importer importer;
  AssimpReadReport report;
  const aiScene* ai = read_reporting(importer, path, rules, report);
  return finish_import(report, ai, path, options);
}

}  // namespace facet::io
