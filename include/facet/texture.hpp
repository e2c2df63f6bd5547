// Texture: an image with its mipmap chain, and how it is sampled (filter, wrap modes).
// Texels are stored as 8-bit RGBA (sRGB-encoded or linear), 32-bit float RGBA (HDR) or one
// 32-bit float (depth images); sampling always returns linear RGBA.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <string>
#include <vector>

namespace facet {

enum class Filter {
  nearest,    // the nearest texel of the base level
  bilinear,   // 2x2 texels of the base level
  trilinear,  // bilinear in the two nearest mip levels, blended by the level of detail
};

enum class Wrap { repeat, clamp_to_edge, mirrored_repeat };

struct Sampler {
  Filter filter = Filter::trilinear;
  Wrap wrap_u = Wrap::repeat;
  Wrap wrap_v = Wrap::repeat;
};

class Texture {
 public:
  enum class Format {
    rgba8,
    rgba32f,
    r32f,  // one float a texel (a depth image), read as (v, v, v, 1)
  };

  // One level of the mipmap chain; level 0 is the full image. Rows top first.
  struct Level {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8;  // Format::rgba8
    std::vector<float> rgba32f;       // Format::rgba32f
    std::vector<float> r32f;          // Format::r32f
  };

  // Builds the texture and its full mipmap chain (box filter in linear space, down to 1x1).
  // srgb: the color channels of rgba8 data are sRGB-encoded (decoded when sampled); alpha is
  // always linear. Throws facet::Error on a bad size or data length.
  static std::shared_ptr<Texture> from_rgba8(int width, int height, std::vector<std::uint8_t> rgba,
                                             bool srgb, std::string name = {});
  static std::shared_ptr<Texture> from_rgba32f(int width, int height, std::vector<float> rgba,
                                               std::string name = {});
  static std::shared_ptr<Texture> from_r32f(int width, int height, std::vector<float> values,
                                            std::string name = {});

  int width() const { return levels_[0].width; }
  int height() const { return levels_[0].height; }
  int level_count() const { return static_cast<int>(levels_.size()); }
  const Level& level(int i) const { return levels_[i]; }
  Format format() const { return format_; }
  bool srgb() const { return srgb_; }
  const std::string& name() const { return name_; }  // file name or "embedded:N"

  // Linear RGBA of one texel; y counts stored rows, top first (unlike v). Throws facet::Error
  // if outside the level.
  glm::vec4 texel(int level, int x, int y) const;

  // Samples at uv (u right, v up: v = 0 is the bottom row of the image, as in OpenGL) with
  // the given level of detail (0 = base level; only trilinear uses it).
  glm::vec4 sample(const Sampler& sampler, glm::vec2 uv, float lod = 0.0f) const;

  // Every level as linear float RGBA in one array, level l starting at float offsets[l]: what
  // the sampler reads where it exists. offsets holds zeros after the last level up to a multiple
  // of kLevelOffsetsPadding entries, so SIMD code may load it a whole vector at a time. texels
  // is null when the texture keeps no such copy (rgba32f textures, and rgba8 ones over 2^20
  // texels): the sampler then reads the levels themselves.
  static constexpr std::size_t kLevelOffsetsPadding = 16;
  struct LinearLevels {
    const float* texels = nullptr;
    const std::int32_t* offsets = nullptr;
  };
  LinearLevels linear_levels() const {
    return {linear_.empty() ? nullptr : linear_.data(), linear_offsets_.data()};
  }

 private:
  friend class RenderTexture;
  Texture() = default;
  // For RenderTexture: a texture whose base level trades buffers with its target's framebuffer
  // after each frame, with the whole mip chain or the base level alone;
  // refresh_from_base_level() then filters the levels above it and decodes the linear copy, in
  // place, allocating nothing.
  static std::shared_ptr<Texture> render_target(int width, int height, Format format, bool srgb,
                                                bool mipmaps, std::string name);
  Level& base_level() { return levels_[0]; }
  void refresh_from_base_level();
  void keep_linear_copy();    // sizes linear_ and linear_offsets_, then decodes
  void decode_linear_copy();  // rewrites linear_ from the rgba8 levels
  std::vector<Level> levels_;
  Format format_ = Format::rgba8;
  bool srgb_ = false;
  std::string name_;
  // The rgba8 levels decoded once to linear float RGBA, which the sampler reads: one 16-byte load
  // a texel instead of four table lookups. All levels in one array (level l from float
  // linear_offsets_[l]), so that SIMD gathers index them with 32 bits. Empty for rgba32f
  // textures (levels_ already are) and for very large rgba8 ones (memory; see
  // kMaxLinearTexels in texture.cpp).
  std::vector<float> linear_;
  std::vector<std::int32_t> linear_offsets_;
};

// Reads an image file: PNG, JPEG, TGA, BMP, HDR (stb_image) or PPM/PGM P2/P3/P5/P6 (facet's own
// reader). srgb applies to 8-bit color data (true for base color and emissive maps, false for
// normal, roughness and other data maps). Throws facet::Error naming the file and the problem.
std::shared_ptr<Texture> load_texture(const std::string& path, bool srgb);
// The same from an encoded image in memory (embedded glTF images); name is used in errors.
std::shared_ptr<Texture> load_texture_from_memory(const std::uint8_t* data, std::size_t size,
                                                  bool srgb, const std::string& name);

// A magenta/black checker drawn where a texture is missing, so the gap is visible.
std::shared_ptr<const Texture> missing_texture();

}  // namespace facet
