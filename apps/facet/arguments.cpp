// Value parsers for the command line (see arguments.hpp).
#include "arguments.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include "facet/color.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/renderer.hpp"

namespace facet::cli {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

template <class T>
bool parse_number(const std::string& text, T& out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end;
}

}  // namespace

ImageSize parse_size(const std::string& flag, const std::string& text) {
  auto parts = split(text, 'x');
  ImageSize size;
  if (parts.size() != 2 || !parse_number(parts[0], size.width) ||
      !parse_number(parts[1], size.height)) {
    throw Error(flag + ": expected WIDTHxHEIGHT such as 1920x1080, got '" + text + "'");
  }
  if (size.width < 1 || size.height < 1 || size.width > Framebuffer::kMaxSize ||
      size.height > Framebuffer::kMaxSize) {
    throw Error(flag + ": " + text + " is outside 1x1 .. 8192x8192");
  }
  return size;
}

glm::vec3 parse_vec3(const std::string& flag, const std::string& text) {
  auto parts = split(text, ',');
  glm::vec3 v;
  if (parts.size() != 3 || !parse_number(parts[0], v.x) || !parse_number(parts[1], v.y) ||
      !parse_number(parts[2], v.z) || !std::isfinite(v.x) || !std::isfinite(v.y) ||
      !std::isfinite(v.z)) {
    throw Error(flag + ": expected three numbers x,y,z such as 0,1.5,-2, got '" + text + "'");
  }
  return v;
}

glm::vec3 parse_color(const std::string& flag, const std::string& text) {
  glm::vec3 c;
  try {
    c = parse_vec3(flag, text);
  } catch (const Error&) {
    throw Error(flag + ": expected r,g,b with each in [0, 1] such as 0.1,0.2,0.3, got '" + text +
                "'");
  }
  for (int i = 0; i < 3; ++i) {
    if (c[i] < 0.0f || c[i] > 1.0f) {
      throw Error(flag + ": color components must be in [0, 1], got '" + text + "'");
    }
  }
  return srgb_to_linear(c);
}

void check_threads(int threads) {
  if (threads < 0 || threads > RenderSettings::kMaxThreads) {
    throw Error("--threads: must be 0 (all cores) or 1 to " +
                std::to_string(RenderSettings::kMaxThreads) + ", got " + std::to_string(threads));
  }
}

void check_msaa(int samples) {
  if (samples != 1 && samples != 2 && samples != 4 && samples != 8 && samples != 16) {
    throw Error("--msaa: must be 1, 2, 4, 8 or 16 samples per pixel, got " +
                std::to_string(samples));
  }
}

std::string msaa_help(int default_samples) {
  return "Multisample anti-aliasing: samples per pixel, 1 (off), 2, 4, 8 or 16 (default: " +
         std::to_string(default_samples) + ")";
}

namespace {
constexpr ToneMapping kToneMappings[] = {ToneMapping::none, ToneMapping::pbr_neutral,
                                         ToneMapping::aces};
}  // namespace

const char* to_string(ToneMapping curve) {
  switch (curve) {
    case ToneMapping::pbr_neutral:
      return "pbr-neutral";
    case ToneMapping::aces:
      return "aces";
    default:
      return "none";
  }
}

ToneMapping parse_tone_mapping(const std::string& text) {
  for (ToneMapping curve : kToneMappings) {
    if (text == to_string(curve)) return curve;
  }
  throw Error("--tone-mapping: expected none, pbr-neutral or aces, got '" + text + "'");
}

std::string tone_mapping_help(ToneMapping default_curve) {
  return std::string(
             "How colors brighter than white are shown: pbr-neutral (Khronos PBR Neutral: "
             "colors kept, highlights roll off to white), aces (ACES filmic: more "
             "contrast) or none (clipped); the background color is never mapped "
             "(default: ") +
         to_string(default_curve) + ")";
}

bool parse_on_off(const std::string& flag, const std::string& text) {
  if (text == "on") return true;
  if (text == "off") return false;
  throw Error(flag + ": expected on or off, got '" + text + "'");
}

int parse_shadow_map_size(const std::string& text, ImageSize image) {
  if (text == "auto") {
    int size = 256;
    while (size < std::max(image.width, image.height) && size < 2048) size *= 2;
    return size;
  }
  int size = 0;
  if (!parse_number(text, size) || size < RenderSettings::kMinShadowMapSize ||
      size > Framebuffer::kMaxSize) {
    throw Error("--shadow-map-size: expected auto or " +
                std::to_string(RenderSettings::kMinShadowMapSize) + " to " +
                std::to_string(Framebuffer::kMaxSize) + " texels, got '" + text + "'");
  }
  return size;
}

int parse_tile_size(const std::string& text) {
  if (text == "auto") return RenderSettings::kAutoTileSize;
  int size = 0;
  if (!parse_number(text, size) || (size != 16 && size != 32 && size != 64 && size != 128)) {
    throw Error("--tile-size: expected auto, 16, 32, 64 or 128, got '" + text + "'");
  }
  return size;
}

int parse_shadow_cascades(const std::string& text) {
  if (text == "auto") return RenderSettings::kAutoShadowCascades;
  int cascades = 0;
  if (!parse_number(text, cascades) || cascades < 1 ||
      cascades > RenderSettings::kMaxShadowCascades) {
    throw Error("--shadow-cascades: expected auto or 1 to " +
                std::to_string(RenderSettings::kMaxShadowCascades) + ", got '" + text + "'");
  }
  return cascades;
}

}  // namespace facet::cli
