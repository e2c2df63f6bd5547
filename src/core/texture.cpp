// Textures: construction with the mipmap chain and texel fetch. Written once at load
// (from_rgba8 / from_rgba32f), then read by the shading stage for every textured pixel through
// the SIMD sampler (texture_sample-inl.h), which sample() calls for one lookup.
#include "facet/texture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/color.hpp"
#include "core/parallel.hpp"
#include "core/simd_target.hpp"
#include "core/srgb_row.hpp"
#include "core/texel.hpp"
#include "core/texture_sampler.hpp"
#include "core/unorm8_mip_row.hpp"
#include "facet/error.hpp"

namespace facet {
namespace {

constexpr int kMaxTextureSize = 16384;

// rgba8 textures up to this many base texels also keep their levels decoded to linear float
// (Texture::linear_): 16 bytes a texel, so at most 16 MiB plus a third for the mip chain.
// Larger ones decode through the tables below on every fetch (the same values, more work).
constexpr std::size_t kMaxLinearTexels = std::size_t{1} << 20;

std::string label(const std::string& name) { return name.empty() ? "texture" : name; }

void check_size(int width, int height, std::size_t values, std::size_t expected_per_texel,
                const std::string& name) {
  if (width < 1 || height < 1 || width > kMaxTextureSize || height > kMaxTextureSize) {
    throw Error(label(name) + ": texture size " + std::to_string(width) + "x" +
                std::to_string(height) + " outside 1x1 .. " + std::to_string(kMaxTextureSize) +
                "x" + std::to_string(kMaxTextureSize));
  }
  const std::size_t expected = static_cast<std::size_t>(width) * height * expected_per_texel;
  if (values != expected) {
    throw Error(label(name) + ": texture data has " + std::to_string(values) + " values, " +
                std::to_string(width) + "x" + std::to_string(height) +
                (expected_per_texel == 1 ? " needs " : " RGBA needs ") + std::to_string(expected));
  }
}

inline glm::vec4 to_vec4(Texel t) { return {t[0], t[1], t[2], t[3]}; }

// Readers of linear RGBA texels of one level, one type per storage format, so the mipmap
// filter below is compiled once per format and fetches texels without a format branch.
struct Rgba8Reader {
  const std::uint8_t* texels;
  int width, height;
  const float* color;  // decode table for r, g, b: sRGB or unorm
  const float* alpha;  // decode table for alpha: always unorm (alpha is never sRGB)

  Rgba8Reader(const Texture::Level& level, bool srgb)
      : texels(level.rgba8.data()), width(level.width), height(level.height) {
    const TexelDecode& tables = texel_decode();
    color = tables.color(srgb);
    alpha = tables.unorm.data();
  }
  Texel operator()(int x, int row) const {
    return decode_rgba8(texels + (static_cast<std::size_t>(row) * width + x) * 4, color, alpha);
  }
};

// Linear float RGBA: rgba32f levels, and rgba8 levels decoded once at load (Texture::linear_).
struct FloatReader {
  const float* texels;
  int width, height;

  Texel operator()(int x, int row) const {
    return load_texel(texels + (static_cast<std::size_t>(row) * width + x) * 4);
  }
};

// --- mipmap construction ----------------------------------------------------------------

// One float a texel (r32f levels), read as (v, v, v, 1).
struct R32fReader {
  const float* texels;
  int width, height;

  Texel operator()(int x, int row) const {
    const float v = texels[static_cast<std::size_t>(row) * width + x];
    return Texel{v, v, v, 1.0f};
  }
};

// Linear RGBA of one texel, whatever the format (texel(); not the hot path).
glm::vec4 linear_texel(const Texture::Level& level, bool srgb, int x, int y) {
  if (!level.r32f.empty())
    return to_vec4(R32fReader{level.r32f.data(), level.width, level.height}(x, y));
  if (!level.rgba32f.empty()) {
    return to_vec4(FloatReader{level.rgba32f.data(), level.width, level.height}(x, y));
  }
  return to_vec4(Rgba8Reader(level, srgb)(x, y));
}

// Stores linear texels into a level: as they are in a float level; in an 8-bit one through the
// row kernels (core/srgb_row.hpp) of the target chosen when the writer is made, the color
// channels sRGB-encoded or rounded as alpha always is.
class LevelWriter {
 public:
  explicit LevelWriter(bool srgb) {
    const SimdTarget target = chosen_simd_target();
    if (srgb) {
      encode_srgb_ = shading::encode_srgb_row_kernel(target);
    } else {
      round_unorm8_ = shading::round_unorm8_row_kernel(target);
    }
  }

  // Texels x to x + count - 1 of row y (of an r32f level, their red channel).
  void store(Texture::Level& level, int x, int y, const glm::vec4* linear, int count) const {
    const std::size_t first = static_cast<std::size_t>(y) * level.width + x, i = first * 4;
    if (!level.r32f.empty()) {
      for (int k = 0; k < count; ++k) level.r32f[first + k] = linear[k].r;
    } else if (!level.rgba32f.empty()) {
      std::memcpy(&level.rgba32f[i], linear, sizeof(glm::vec4) * count);
    } else if (encode_srgb_ != nullptr) {
      encode_srgb_(linear, count, 1.0f, &level.rgba8[i]);
    } else {
      round_unorm8_(linear, count, &level.rgba8[i]);
    }
  }

 private:
  shading::EncodeSrgbRowKernel encode_srgb_ = nullptr;
  shading::RoundUnorm8RowKernel round_unorm8_ = nullptr;
};

// Storage for the level after src: each side halved (rounded down, at least 1).
Texture::Level next_level_storage(const Texture::Level& src) {
  Texture::Level dst;
  dst.width = std::max(1, src.width / 2);
  dst.height = std::max(1, src.height / 2);
  const std::size_t texels = static_cast<std::size_t>(dst.width) * dst.height;
  if (!src.r32f.empty()) {
    dst.r32f.resize(texels);
  } else if (!src.rgba32f.empty()) {
    dst.rgba32f.resize(texels * 4);
  } else {
    dst.rgba8.resize(texels * 4);
  }
  return dst;
}

// Runs filter_rows(first, end) over the rows [0, rows) of a level, in bands of kBandRows rows
// in parallel (a render texture's chain is part of every frame); each texel is computed the
// same way whichever worker runs its band.
template <class FilterRows>
void for_each_band(int rows, const FilterRows& filter_rows) {
  constexpr int kBandRows = 16;
  const int bands = (rows + kBandRows - 1) / kBandRows;
  auto filter_band = [&](int band) {
    filter_rows(band * kBandRows, std::min(rows, (band + 1) * kBandRows));
  };
  if (bands == 1) {
    filter_band(0);
  } else {
    parallel_tasks(bands, default_workers(), [&](int band, int) { filter_band(band); });
  }
}

// Fills dst, the level after src (next_level_storage): each texel the average, in linear space,
// of the 2x2 source texels it covers, or of fewer where a side is already 1. (On odd sizes the
// last source row/column is dropped, as a plain 2x2 box filter does.) The averages are stored
// up to kChunkTexels of a row at a time, from a buffer on the stack: a render texture refreshes
// its chain every frame, and steady-state frames allocate nothing.
template <class Reader>
void downsample(const Texture::Level& src, const Reader& read, const LevelWriter& write,
                Texture::Level& dst) {
  constexpr int kChunkTexels = 64;
  const int nx = src.width > 1 ? 2 : 1, ny = src.height > 1 ? 2 : 1;
  const float weight = 1.0f / static_cast<float>(nx * ny);
  for_each_band(dst.height, [&](int first_row, int end_row) {
    glm::vec4 averages[kChunkTexels];
    for (int y = first_row; y < end_row; ++y) {
      for (int first = 0; first < dst.width; first += kChunkTexels) {
        const int count = std::min(kChunkTexels, dst.width - first);
        for (int i = 0; i < count; ++i) {
          const int x = first + i;
          glm::vec4 sum(0.0f);
          for (int dy = 0; dy < ny; ++dy) {
            for (int dx = 0; dx < nx; ++dx) sum += to_vec4(read(2 * x + dx, 2 * y + dy));
          }
          averages[i] = sum * weight;
        }
        write.store(dst, first, y, averages, count);
      }
    }
  });
}

// downsample() of an 8-bit level read as unorm (not sRGB) whose sides are both above 1: a row
// at a time from the two above (unorm8_mip_row.hpp: exactly the rounded float average, in
// integers), in bands of rows.
void downsample_unorm8(const Texture::Level& src, Texture::Level& dst) {
  const HalveUnorm8RowKernel halve = halve_unorm8_row_kernel(chosen_simd_target());
  const std::size_t src_stride = static_cast<std::size_t>(src.width) * 4;
  for_each_band(dst.height, [&](int first_row, int end_row) {
    for (int y = first_row; y < end_row; ++y) {
      const std::uint8_t* top = src.rgba8.data() + 2 * static_cast<std::size_t>(y) * src_stride;
      halve(top, top + src_stride, dst.width,
            dst.rgba8.data() + static_cast<std::size_t>(y) * dst.width * 4);
    }
  });
}

// Filters each level from the previous (stored) one, as glGenerateMipmap does: one pass per
// level, into the levels' existing storage.
void filter_mip_chain(std::vector<Texture::Level>& levels, bool srgb) {
  const LevelWriter write(srgb);
  for (std::size_t l = 1; l < levels.size(); ++l) {
    const Texture::Level& last = levels[l - 1];
    if (!last.r32f.empty()) {
      downsample(last, R32fReader{last.r32f.data(), last.width, last.height}, write, levels[l]);
    } else if (!last.rgba32f.empty()) {
      downsample(last, FloatReader{last.rgba32f.data(), last.width, last.height}, write, levels[l]);
    } else if (!srgb && last.width > 1 && last.height > 1) {
      downsample_unorm8(last, levels[l]);
    } else {
      downsample(last, Rgba8Reader(last, srgb), write, levels[l]);
    }
  }
}

// Adds the levels down to 1x1 after levels[0], then filters them.
void build_mip_chain(std::vector<Texture::Level>& levels, bool srgb) {
  while (levels.back().width > 1 || levels.back().height > 1) {
    levels.push_back(next_level_storage(levels.back()));
  }
  filter_mip_chain(levels, srgb);
}

}  // namespace

const TexelDecode& texel_decode() {
  static const TexelDecode kTables = [] {
    TexelDecode tables;
    for (int i = 0; i < 256; ++i) {
      tables.srgb[i] = shading::decode_srgb8(static_cast<std::uint8_t>(i));
      tables.unorm[i] = static_cast<float>(i) / 255.0f;
    }
    return tables;
  }();
  return kTables;
}

std::shared_ptr<Texture> Texture::from_rgba8(int width, int height, std::vector<std::uint8_t> rgba,
                                             bool srgb, std::string name) {
  check_size(width, height, rgba.size(), 4, name);
  std::shared_ptr<Texture> texture(new Texture());  // the constructor is private: no make_shared
  texture->format_ = Format::rgba8;
  texture->srgb_ = srgb;
  texture->name_ = std::move(name);
  texture->levels_.push_back(Level{width, height, std::move(rgba), {}, {}});
  build_mip_chain(texture->levels_, srgb);
  if (static_cast<std::size_t>(width) * height <= kMaxLinearTexels) texture->keep_linear_copy();
  return texture;
}

void Texture::keep_linear_copy() {
  std::size_t total = 0;
  linear_offsets_.clear();
  for (const Level& level : levels_) {
    linear_offsets_.push_back(static_cast<std::int32_t>(total));
    total += level.rgba8.size();
  }
  linear_offsets_.resize((linear_offsets_.size() + kLevelOffsetsPadding - 1) /
                         kLevelOffsetsPadding * kLevelOffsetsPadding);  // zeros (LinearLevels)
  linear_.resize(total);
  decode_linear_copy();
}

void Texture::decode_linear_copy() {
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    const Level& level = levels_[l];
    const Rgba8Reader read(level, srgb_);
    float* linear = linear_.data() + linear_offsets_[l];
    for (int y = 0; y < level.height; ++y) {
      for (int x = 0; x < level.width; ++x) {
        const Texel t = read(x, y);
        std::memcpy(&linear[(static_cast<std::size_t>(y) * level.width + x) * 4], &t, sizeof t);
      }
    }
  }
}

std::shared_ptr<Texture> Texture::render_target(int width, int height, Format format, bool srgb,
                                                bool mipmaps, std::string name) {
  const std::size_t texels = static_cast<std::size_t>(width) * height;
  std::shared_ptr<Texture> texture(new Texture());
  texture->format_ = format;
  texture->srgb_ = format == Format::rgba8 && srgb;
  texture->name_ = std::move(name);
  Level base{width, height, {}, {}, {}};
  if (format == Format::rgba8) {
    base.rgba8.resize(texels * 4);
  } else if (format == Format::rgba32f) {
    base.rgba32f.resize(texels * 4);
  } else {
    base.r32f.resize(texels);
  }
  texture->levels_.push_back(std::move(base));
  if (mipmaps) build_mip_chain(texture->levels_, texture->srgb_);
  if (format == Format::rgba8 && static_cast<std::size_t>(width) * height <= kMaxLinearTexels) {
    texture->keep_linear_copy();
  }
  return texture;
}

void Texture::refresh_from_base_level() {
  filter_mip_chain(levels_, srgb_);
  if (!linear_.empty()) decode_linear_copy();
}

std::shared_ptr<Texture> Texture::from_rgba32f(int width, int height, std::vector<float> rgba,
                                               std::string name) {
  check_size(width, height, rgba.size(), 4, name);
  std::shared_ptr<Texture> texture(new Texture());
  texture->format_ = Format::rgba32f;
  texture->name_ = std::move(name);
  texture->levels_.push_back(Level{width, height, {}, std::move(rgba), {}});
  build_mip_chain(texture->levels_, false);
  return texture;
}

std::shared_ptr<Texture> Texture::from_r32f(int width, int height, std::vector<float> values,
                                            std::string name) {
  check_size(width, height, values.size(), 1, name);
  std::shared_ptr<Texture> texture(new Texture());
  texture->format_ = Format::r32f;
  texture->name_ = std::move(name);
  texture->levels_.push_back(Level{width, height, {}, {}, std::move(values)});
  build_mip_chain(texture->levels_, false);
  return texture;
}

// x, y address the level as stored: y = 0 is the TOP row (unlike v in sample()).
glm::vec4 Texture::texel(int level, int x, int y) const {
  if (level < 0 || level >= level_count() || x < 0 || y < 0 || x >= levels_[level].width ||
      y >= levels_[level].height) {
    throw Error(label(name_) + ": texel (" + std::to_string(x) + ", " + std::to_string(y) +
                ") of level " + std::to_string(level) + " is outside the texture");
  }
  return linear_texel(levels_[level], srgb_, x, y);
}

glm::vec4 Texture::sample(const Sampler& sampler, glm::vec2 uv, float lod) const {
  float rgba[1][4];
  sample_at_kernel(chosen_simd_target())(*this, sampler, &uv.x, &uv.y, &lod, 1, rgba);
  return {rgba[0][0], rgba[0][1], rgba[0][2], rgba[0][3]};
}

std::shared_ptr<const Texture> missing_texture() {
  // Built once, shared by every material whose texture could not be loaded. 8x8 cells of
  // 8x8 texels: big cells so the pattern stays crisp under bilinear filtering.
  static const std::shared_ptr<Texture> kMissing = [] {
    constexpr int kSize = 64, kCell = 8;
    std::vector<std::uint8_t> rgba(std::size_t{kSize} * kSize * 4);
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const bool magenta = ((x / kCell) + (y / kCell)) % 2 == 0;
        std::uint8_t* p = &rgba[static_cast<std::size_t>(y * kSize + x) * 4];
        p[0] = p[2] = magenta ? 255 : 0;
        p[1] = 0;
        p[3] = 255;
      }
    }
    return Texture::from_rgba8(kSize, kSize, std::move(rgba), false, "missing texture");
  }();
  return kMissing;
}

}  // namespace facet
