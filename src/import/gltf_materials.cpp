// import_gltf_materials() (gltf_internal.hpp): glTF materials to facet Materials, and the
// images they use decoded to Textures. Runs once per model at load time.
//
//   pbrMetallicRoughness        pbr, every factor and map; samplers' wrap and filters
//   KHR_materials_pbrSpecularGlossiness   pbr, the factors converted (convert_specular_glossiness),
//                               the diffuse map as the base color map, the gloss map baked into
//                               a roughness map (the specular color stays the factors')
//   KHR_materials_unlit         unlit
//   KHR_materials_emissive_strength       scales the emissive factor
//   KHR_materials_transmission  approximated as blending (facet draws no refraction): the
//                               surface lets through transmission x (1 - F0) of the light,
//                               filtered by its color, so the background is dimmed by the
//                               color's luminance and the color fills in: a clear glass is
//                               nearly invisible but for its highlights, a green one tints
//                               green (alpha = 1 - luminance x transmission x (1 - F0), >= 0.1)
//   KHR_materials_ior           F0 = ((ior - 1) / (ior + 1))², which sets how much a
//                               transmissive surface reflects, and the specular weight below
//   KHR_materials_specular      the dielectric specular is F0 x specularColor x specular;
//                               facet's PBR lobe has F0 = 0.04 (ior 1.5), so a weaker specular
//                               (weight = that / 0.04, below 1) is drawn as a rougher, dimmer
//                               highlight: roughness moves toward 1 by (1 - weight); a stronger
//                               one stays as it is. Their textures are not read
//   KHR_materials_sheen         the velvet's sheen lobe as its average contribution: the base
//                               color becomes base (1 - 0.5 max(sheen)) + 0.5 sheenColor (the
//                               layering of the extension with a directional albedo of 0.5), a
//                               base color map baked to match; the sheen maps are not read
//   KHR_materials_clearcoat     approximated in the one specular lobe: roughness moves toward
//                               the coat's as far as clearcoatFactor says
//   (volume and the rest are not read: the base layer is drawn)
//   KHR_texture_transform       each map's own transform (TextureMap::transform)
//   texCoord                    facet meshes carry one texture coordinate set: a material reads
//                               the set of its base color map (else its first map's); maps that
//                               ask for another set are warned about once, naming the material
#include <algorithm>
#include <cmath>
#include <string>

#include "facet/color.hpp"
#include "facet/error.hpp"
#include "import/gltf_internal.hpp"

namespace facet::io {
namespace {

// glTF sampler enums (glTF 2.0 §5.26, the OpenGL values).
constexpr int kGlNearest = 9728, kGlLinear = 9729;
constexpr int kGlClampToEdge = 33071, kGlMirroredRepeat = 33648;

double number(const tinygltf::Value& object, const std::string& key, double fallback) {
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsNumber()) return fallback;
  const double d = v.GetNumberAsDouble();
  return std::isfinite(d) ? d : fallback;
}

int integer(const tinygltf::Value& object, const std::string& key, int fallback) {
  const tinygltf::Value& v = object.Get(key);
  return v.IsInt() ? v.GetNumberAsInt() : fallback;
}

glm::vec4 vector(const tinygltf::Value& object, const std::string& key, glm::vec4 fallback) {
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsArray()) return fallback;
  for (int i = 0; i < 4 && i < static_cast<int>(v.ArrayLen()); ++i) {
    const tinygltf::Value& c = v.Get(i);
    if (c.IsNumber() && std::isfinite(c.GetNumberAsDouble()))
      fallback[i] = static_cast<float>(c.GetNumberAsDouble());
  }
  return fallback;
}

template <class Vector>
glm::vec4 factors(const Vector& values, glm::vec4 fallback) {
  for (std::size_t i = 0; i < 4 && i < values.size(); ++i) {
    if (std::isfinite(values[i])) fallback[static_cast<int>(i)] = static_cast<float>(values[i]);
  }
  return fallback;
}

float clamp01(double v) { return std::clamp(static_cast<float>(v), 0.0f, 1.0f); }

// The sheen lobe's albedo averaged over directions, for the sheen approximation (a Charlie
// sheen's directional albedo is between about 0.3 and 0.6 for the roughnesses velvet uses).
constexpr float kSheenAlbedo = 0.5f;
// facet's PBR shader's dielectric reflectance at normal incidence (ior 1.5).
constexpr float kFacetF0 = 0.04f;

float f0_of_ior(double ior) {
  const double r = (ior - 1.0) / (ior + 1.0);
  return static_cast<float>(r * r);
}

// A base color map with the sheen baked in: map x factor x (1 - k max(sheen)) + k sheen, in
// linear light, encoded back to sRGB (the material's color factor becomes white).
std::shared_ptr<const Texture> base_with_sheen(const Texture& map, glm::vec3 factor,
                                               glm::vec3 sheen) {
  if (map.format() != Texture::Format::rgba8) return nullptr;
  const Texture::Level& level = map.level(0);
  const float keep = 1.0f - kSheenAlbedo * std::max({sheen.r, sheen.g, sheen.b});
  std::vector<std::uint8_t> baked(level.rgba8);
  for (std::size_t i = 0; i + 3 < baked.size(); i += 4) {
    glm::vec3 c(baked[i], baked[i + 1], baked[i + 2]);
    c /= 255.0f;
    if (map.srgb()) c = srgb_to_linear(c);
    c = glm::min(c * factor * keep + kSheenAlbedo * sheen, glm::vec3(1.0f));
    if (map.srgb()) c = linear_to_srgb(c);
    for (int k = 0; k < 3; ++k)
      baked[i + k] = static_cast<std::uint8_t>(std::lround(c[k] * 255.0f));
  }
  return Texture::from_rgba8(level.width, level.height, std::move(baked), map.srgb(),
                             map.name() + " (with sheen)");
}

// A specular-glossiness map's gloss (alpha, times the factor) as the packed map the PBR shader
// reads: roughness 1 - gloss in G, 1 in B so that the material's metallic factor (converted
// from the factors) stays what it is.
std::shared_ptr<const Texture> roughness_from_gloss(const Texture& map, float glossiness) {
  if (map.format() != Texture::Format::rgba8) return nullptr;
  const Texture::Level& level = map.level(0);
  std::vector<std::uint8_t> packed(level.rgba8.size());
  for (std::size_t i = 0; i + 3 < packed.size(); i += 4) {
    const float gloss = level.rgba8[i + 3] / 255.0f * glossiness;
    packed[i + 0] = 0;
    packed[i + 1] = static_cast<std::uint8_t>(std::lround((1.0f - gloss) * 255.0f));
    packed[i + 2] = 255;
    packed[i + 3] = 255;
  }
  return Texture::from_rgba8(level.width, level.height, std::move(packed), false,
                             map.name() + " (roughness from gloss)");
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& map, const char* name) {
  auto it = map.find(name);
  return it == map.end() ? nullptr : &it->second;
}

Wrap wrap_from(int mode) {
  if (mode == kGlClampToEdge) return Wrap::clamp_to_edge;
  if (mode == kGlMirroredRepeat) return Wrap::mirrored_repeat;
  return Wrap::repeat;
}

// KHR_texture_transform's uv' = T(offset) R(rotation) S(scale) uv, in glTF's coordinates (v
// down), conjugated by v -> 1 - v for facet's (v up).
glm::mat3 texture_transform(const tinygltf::Value& t) {
  const glm::vec4 offset = vector(t, "offset", glm::vec4(0.0f));
  const glm::vec4 scale = vector(t, "scale", glm::vec4(1.0f));
  const float rotation = static_cast<float>(number(t, "rotation", 0.0));
  const float c = std::cos(rotation), s = std::sin(rotation);
  glm::mat3 m(1.0f);  // columns
  m[0] = glm::vec3(c * scale.x, -s * scale.x, 0.0f);
  m[1] = glm::vec3(s * scale.y, c * scale.y, 0.0f);
  m[2] = glm::vec3(offset.x, offset.y, 1.0f);
  glm::mat3 flip_v(1.0f);
  flip_v[1][1] = -1.0f;
  flip_v[2][1] = 1.0f;
  return flip_v * m * flip_v;
}

// A texture reference as the material gives it (TextureInfo and its kin).
struct TextureRef {
  int index = -1;
  int texcoord = 0;
  const tinygltf::ExtensionMap* extensions = nullptr;
};

template <class Info>
TextureRef ref(const Info& info) {
  return {info.index, info.texCoord, &info.extensions};
}

// A texture reference inside an extension's JSON ({"index": 0, "texCoord": 1, ...}).
TextureRef ref(const tinygltf::Value& object, const char* key) {
  const tinygltf::Value& info = object.Get(key);
  TextureRef r;
  if (!info.IsObject()) return r;
  r.index = integer(info, "index", -1);
  r.texcoord = integer(info, "texCoord", 0);
  return r;  // (extensions of textures inside extensions are not read)
}

class Converter {
 public:
  Converter(const GltfFile& file, const ImportOptions& options) : file_(file), options_(options) {}

  GltfMaterials convert() {
    for (std::size_t i = 0; i < file_.model.materials.size(); ++i) {
      sets_.clear();
      out_.materials.push_back(material(file_.model.materials[i]));
      out_.texcoord_set.push_back(texcoord_set(out_.materials.back()));
    }
    return std::move(out_);
  }

 private:
  Material material(const tinygltf::Material& m) {
    Material out;
    out.name = m.name;
    out.shading = ShadingModel::pbr;
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    out.base_color = glm::max(factors(pbr.baseColorFactor, glm::vec4(1.0f)), glm::vec4(0.0f));
    out.metallic = clamp01(pbr.metallicFactor);
    out.roughness = clamp01(pbr.roughnessFactor);
    out.base_color_map = map(ref(pbr.baseColorTexture), true, 0);
    out.metallic_roughness_map = map(ref(pbr.metallicRoughnessTexture), false, 1);
    out.normal_map = map(ref(m.normalTexture), false, 2);
    out.normal_scale =
        std::isfinite(m.normalTexture.scale) ? static_cast<float>(m.normalTexture.scale) : 1.0f;
    out.occlusion_map = map(ref(m.occlusionTexture), false, 3);
    out.occlusion_strength = clamp01(m.occlusionTexture.strength);
    out.emissive_map = map(ref(m.emissiveTexture), true, 4);
    out.emissive = glm::max(glm::vec3(factors(m.emissiveFactor, glm::vec4(0.0f))), glm::vec3(0.0f));
    if (m.alphaMode == "MASK") out.alpha_mode = AlphaMode::mask;
    if (m.alphaMode == "BLEND") out.alpha_mode = AlphaMode::blend;
    out.alpha_cutoff = std::isfinite(m.alphaCutoff) ? static_cast<float>(m.alphaCutoff) : 0.5f;
    if (m.doubleSided) out.cull = CullMode::none;
    extensions(m, out);
    // OPAQUE: "the alpha value is ignored" (glTF 2.0 §3.9.4). The pipeline writes a draw's alpha
    // into the image whatever its mode, so an opaque surface must carry alpha 1 (FBX2glTF's
    // BoxVertexColors has base colors and vertex colors of alpha 0 and is opaque).
    if (out.alpha_mode == AlphaMode::opaque) out.base_color.a = 1.0f;
    return out;
  }

  void extensions(const tinygltf::Material& m, Material& out) {
    if (const auto* sg = extension(m.extensions, "KHR_materials_pbrSpecularGlossiness")) {
      const glm::vec4 diffuse =
          glm::max(vector(*sg, "diffuseFactor", glm::vec4(1.0f)), glm::vec4(0));
      const glm::vec3 specular = glm::vec3(vector(*sg, "specularFactor", glm::vec4(1.0f)));
      convert_specular_glossiness(diffuse, glm::max(specular, glm::vec3(0.0f)),
                                  clamp01(number(*sg, "glossinessFactor", 1.0)), out);
      if (!out.base_color_map) out.base_color_map = map(ref(*sg, "diffuseTexture"), true, 0);
      // The gloss varies over the surface: baked into a roughness map, which the roughness
      // factor (now 1) scales as glTF's does.
      const std::size_t textures_before = out_.textures.size();
      TextureMap gloss = map(ref(*sg, "specularGlossinessTexture"), false, 1);
      if (gloss && gloss.texture != missing_texture()) {
        // The map as decoded is not drawn: only what is baked from it.
        if (out_.textures.size() > textures_before && out_.textures.back() == gloss.texture)
          out_.textures.pop_back();
        gloss.texture =
            roughness_from_gloss(*gloss.texture, clamp01(number(*sg, "glossinessFactor", 1.0)));
        if (gloss.texture) {
          out_.textures.push_back(gloss.texture);
          out.metallic_roughness_map = gloss;
          out.roughness = 1.0f;
        }
      }
    }
    if (extension(m.extensions, "KHR_materials_unlit")) out.shading = ShadingModel::unlit;
    if (const auto* e = extension(m.extensions, "KHR_materials_emissive_strength"))
      out.emissive *= std::max(static_cast<float>(number(*e, "emissiveStrength", 1.0)), 0.0f);
    float f0 = kFacetF0;
    if (const auto* i = extension(m.extensions, "KHR_materials_ior")) {
      const double ior = number(*i, "ior", 1.5);
      // 0 is allowed and means a reflectance of 1 (glTF: "ior = 0 ... F0 = 1.0").
      if (ior == 0.0)
        f0 = 1.0f;
      else if (ior >= 1.0)
        f0 = f0_of_ior(ior);
    }
    if (const auto* s = extension(m.extensions, "KHR_materials_specular")) {
      const float strength = clamp01(number(*s, "specularFactor", 1.0));
      const glm::vec3 tint =
          glm::max(glm::vec3(vector(*s, "specularColorFactor", glm::vec4(1.0f))), glm::vec3(0));
      f0 = std::min(f0 * std::max({tint.r, tint.g, tint.b}), 1.0f) * strength;
    }
    // A dimmer dielectric highlight than facet's lobe draws: spread out instead (metals keep
    // theirs, the extensions leave their F0 alone).
    const float weight = std::min(f0 / kFacetF0, 1.0f);
    out.roughness =
        glm::mix(out.roughness, glm::mix(1.0f, out.roughness, weight), 1 - out.metallic);
    if (const auto* t = extension(m.extensions, "KHR_materials_transmission")) {
      const float transmission = clamp01(number(*t, "transmissionFactor", 0.0));
      if (transmission > 0.0f && out.alpha_mode != AlphaMode::mask) {
        out.alpha_mode = AlphaMode::blend;
        // Light through a colored glass is filtered by its color (and reflected by F0): the
        // background is dimmed by as much, and the glass's own color fills the rest in.
        const glm::vec3 c = glm::min(glm::vec3(out.base_color), glm::vec3(1.0f));
        const float luminance = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
        const float through = transmission * (1.0f - std::min(f0, 1.0f)) * luminance;
        out.base_color.a *= std::max(1.0f - through, 0.1f);
      }
    }
    if (const auto* sheen = extension(m.extensions, "KHR_materials_sheen")) {
      const glm::vec3 color =
          glm::clamp(glm::vec3(vector(*sheen, "sheenColorFactor", glm::vec4(0.0f))), 0.0f, 1.0f);
      add_sheen(color, out);
    }
    if (const auto* c = extension(m.extensions, "KHR_materials_clearcoat")) {
      // One specular lobe: the coat's gloss shows as the surface's, as far as the coat covers it.
      const float coat = clamp01(number(*c, "clearcoatFactor", 0.0));
      const float coat_roughness = clamp01(number(*c, "clearcoatRoughness", 0.0));
      out.roughness = std::min(out.roughness, glm::mix(out.roughness, coat_roughness, coat));
    }
  }

  void add_sheen(glm::vec3 sheen, Material& out) {
    const float strongest = std::max({sheen.r, sheen.g, sheen.b});
    if (!(strongest > 0.0f)) return;
    if (out.base_color_map && out.base_color_map.texture != missing_texture()) {
      auto baked = base_with_sheen(*out.base_color_map.texture, glm::vec3(out.base_color), sheen);
      if (baked) {
        out_.textures.push_back(baked);
        out.base_color_map.texture = std::move(baked);
        out.base_color = glm::vec4(1.0f, 1.0f, 1.0f, out.base_color.a);
        return;
      }
    }
    const glm::vec3 base =
        glm::vec3(out.base_color) * (1.0f - kSheenAlbedo * strongest) + kSheenAlbedo * sheen;
    out.base_color = glm::vec4(base, out.base_color.a);
  }

  // The map a reference names, with its sampler and transform; `slot` orders the maps for the
  // choice of a texture coordinate set (0 base color, 1 metal-rough, 2 normal, ...).
  TextureMap map(const TextureRef& r, bool srgb, int slot) {
    TextureMap out;
    const auto& textures = file_.model.textures;
    if (r.index < 0 || static_cast<std::size_t>(r.index) >= textures.size()) return out;
    const tinygltf::Texture& t = textures[static_cast<std::size_t>(r.index)];
    int set = r.texcoord;
    if (r.extensions) {
      if (const auto* transform = extension(*r.extensions, "KHR_texture_transform")) {
        out.transform = texture_transform(*transform);
        set = integer(*transform, "texCoord", set);
      }
    }
    out.texture = image(t.source, srgb);
    if (!out.texture) return out;
    if (t.sampler >= 0 && static_cast<std::size_t>(t.sampler) < file_.model.samplers.size()) {
      const tinygltf::Sampler& s = file_.model.samplers[static_cast<std::size_t>(t.sampler)];
      out.sampler.wrap_u = wrap_from(s.wrapS);
      out.sampler.wrap_v = wrap_from(s.wrapT);
      if (s.magFilter == kGlNearest) {
        out.sampler.filter = Filter::nearest;  // pixel art asks for crisp texels
      } else if (s.minFilter == kGlNearest || s.minFilter == kGlLinear) {
        out.sampler.filter = Filter::bilinear;  // the file asks for no mipmaps
      }
    }
    sets_.emplace_back(slot, std::max(set, 0));
    return out;
  }

  int texcoord_set(const Material& m) {
    if (sets_.empty()) return 0;
    std::sort(sets_.begin(), sets_.end());
    const int chosen = sets_.front().second;
    for (const auto& [slot, set] : sets_) {
      if (set == chosen) continue;
      warn(options_, file_.path + ": material '" + m.name + "' reads texture coordinate sets " +
                         std::to_string(chosen) + " and " + std::to_string(set) +
                         "; facet reads one set per material, " + std::to_string(chosen) +
                         ", so some of its maps may be misplaced");
      break;
    }
    return chosen;
  }

  // The decoded image, each (image, sRGB) once; a missing or undecodable one is the checker,
  // warned about once.
  std::shared_ptr<const Texture> image(int index, bool srgb) {
    const auto& images = file_.model.images;
    if (index < 0 || static_cast<std::size_t>(index) >= images.size()) return nullptr;
    auto [it, added] = cache_.try_emplace({index, srgb});
    if (!added) return it->second;
    const tinygltf::Image& image = images[static_cast<std::size_t>(index)];
    const std::string name = image.uri.empty() || image.uri.rfind("data:", 0) == 0
                                 ? "embedded:" + std::to_string(index)
                                 : image.uri;
    std::string problem;
    if (image.image.empty()) {
      auto refused = file_.refused.find(image.uri);
      problem = refused != file_.refused.end() ? refused->second : "is missing";
    } else {
      try {
        it->second = load_texture_from_memory(image.image.data(), image.image.size(), srgb, name);
      } catch (const Error& e) {
        problem = std::string("cannot be read (") + e.what() + ")";
      }
    }
    if (!it->second) {
      it->second = missing_texture();
      if (warned_.insert(index).second)
        warn(options_, file_.path + ": texture " + name + " " + problem + "; drawing a checker");
    }
    if (std::find(out_.textures.begin(), out_.textures.end(), it->second) == out_.textures.end())
      out_.textures.push_back(it->second);
    return it->second;
  }

  const GltfFile& file_;
  const ImportOptions& options_;
  GltfMaterials out_;
  std::vector<std::pair<int, int>> sets_;  // (slot, texture coordinate set) of this material
  std::map<std::pair<int, bool>, std::shared_ptr<const Texture>> cache_;
  std::set<int> warned_;
};

}  // namespace

Material gltf_default_material() {
  Material fallback;
  fallback.name = "glTF default";
  fallback.shading = ShadingModel::pbr;
  fallback.metallic = 1.0f;
  fallback.roughness = 1.0f;
  return fallback;
}

GltfMaterials import_gltf_materials(const GltfFile& file, const ImportOptions& options) {
  return Converter(file, options).convert();
}

}  // namespace facet::io
