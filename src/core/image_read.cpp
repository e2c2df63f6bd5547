// Reading texture images: PNG, JPEG, TGA, BMP and HDR through stb_image (Debian libstb-dev),
// PGM/PPM through facet's own reader (pnm.cpp). The result is a Texture with its mip chain.
//
// stb_image is compiled into this file only, with internal linkage (STB_IMAGE_STATIC), so
// libfacet exports no stbi_* symbols that could clash with a user's own copy of stb_image.
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/pnm.hpp"
#include "facet/error.hpp"
#include "facet/texture.hpp"

// Only the formats facet promises (less code exposed to untrusted files); PNM goes to our own
// reader. Larger sides are refused by stb before it allocates, matching Texture's limit.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_TGA
#define STBI_ONLY_BMP
#define STBI_ONLY_HDR
#define STBI_MAX_DIMENSIONS 16384
// Under /usr/include the header is a system header and warns about nothing; from another
// include directory the one warning (with -Wall -Wextra -Wpedantic -Wshadow, GCC 12 and
// Clang 14) is for the static functions this file does not call.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace facet {
namespace {

[[noreturn]] void cannot_read(const std::string& name, const std::string& reason) {
  throw Error(name + ": cannot read image: " + reason);
}

// stb_image's reason for the last failure on this thread (it keeps it thread-local).
std::string stb_reason() {
  const char* reason = stbi_failure_reason();
  return reason ? reason : "unknown error";
}

// Netpbm files start with "P" and a digit (P1..P7); no other supported format can (a TGA's
// second byte, the color map type, is 0 or 1, never an ASCII digit).
bool is_pnm(const std::uint8_t* data, std::size_t size) {
  return size >= 2 && data[0] == 'P' && data[1] >= '1' && data[1] <= '7';
}

struct StbiFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

std::shared_ptr<Texture> decode_stb(const std::uint8_t* data, std::size_t size, bool srgb,
                                    const std::string& name) {
  if (size > static_cast<std::size_t>(INT_MAX)) cannot_read(name, "file larger than 2 GiB");
  const int length = static_cast<int>(size);
  int width = 0, height = 0, channels = 0;
  if (stbi_is_hdr_from_memory(data, length)) {
    // Radiance HDR holds linear light: float texels, the sRGB flag does not apply.
    std::unique_ptr<float, StbiFree> pixels(
        stbi_loadf_from_memory(data, length, &width, &height, &channels, 4));
    if (!pixels) cannot_read(name, stb_reason());
    const float* p = pixels.get();
    std::vector<float> rgba(p, p + static_cast<std::size_t>(width) * height * 4);
    return Texture::from_rgba32f(width, height, std::move(rgba), name);
  }
  std::unique_ptr<stbi_uc, StbiFree> pixels(
      stbi_load_from_memory(data, length, &width, &height, &channels, 4));
  if (!pixels) cannot_read(name, stb_reason());
  const stbi_uc* p = pixels.get();
  std::vector<std::uint8_t> rgba(p, p + static_cast<std::size_t>(width) * height * 4);
  return Texture::from_rgba8(width, height, std::move(rgba), srgb, name);
}

std::vector<std::uint8_t> read_file(const std::string& path) {
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Closer> file(std::fopen(path.c_str(), "rb"));
  if (!file) cannot_read(path, std::strerror(errno));
  std::vector<std::uint8_t> bytes;
  std::uint8_t buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) {
    bytes.insert(bytes.end(), buffer, buffer + n);
  }
  // A directory opens on Linux but fails to read (EISDIR); so does a bad disk.
  if (std::ferror(file.get())) cannot_read(path, std::strerror(errno));
  return bytes;
}

}  // namespace

std::shared_ptr<Texture> load_texture_from_memory(const std::uint8_t* data, std::size_t size,
                                                  bool srgb, const std::string& name) {
  if (data == nullptr || size == 0) cannot_read(name, "no data (empty file)");
  if (is_pnm(data, size)) {
    // parse_pnm's errors read "<name>: <what>"; naming the image this way gives them the
    // same "<name>: cannot read image: <what>" shape as every other format's errors.
    io::PnmImage image = io::parse_pnm(data, size, name + ": cannot read image");
    return Texture::from_rgba8(image.width, image.height, std::move(image.rgba), srgb, name);
  }
  return decode_stb(data, size, srgb, name);
}

std::shared_ptr<Texture> load_texture(const std::string& path, bool srgb) {
  const std::vector<std::uint8_t> bytes = read_file(path);
  return load_texture_from_memory(bytes.data(), bytes.size(), srgb, path);
}

}  // namespace facet
