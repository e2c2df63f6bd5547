// Parsing of the command line's value formats ("1920x1080", "x,y,z", "r,g,b"). Each parser
// throws facet::Error with a message naming the flag and the bad text.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "facet/color.hpp"

namespace facet::cli {

struct ImageSize {
  int width = 1920;
  int height = 1080;
};

// "a, b, c" from a list of names (for help texts and error messages).
template <class Names>
std::string joined(const Names& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

ImageSize parse_size(const std::string& flag, const std::string& text);
glm::vec3 parse_vec3(const std::string& flag, const std::string& text);
// An sRGB color with components in [0, 1], returned as linear RGB.
glm::vec3 parse_color(const std::string& flag, const std::string& text);
// Throws unless --threads is 0 (all cores) or 1 to RenderSettings::kMaxThreads.
void check_threads(int threads);
// Throws unless --msaa is 1, 2, 4, 8 or 16 (RenderSettings::msaa).
void check_msaa(int samples);
// The --msaa help text, with the command's default.
std::string msaa_help(int default_samples);
// --tone-mapping's names: none, pbr-neutral, aces.
ToneMapping parse_tone_mapping(const std::string& text);
const char* to_string(ToneMapping curve);
// The --tone-mapping help text, with the command's default.
std::string tone_mapping_help(ToneMapping default_curve);
// An on|off flag's value (--shadows, --reflections) as a bool; throws for anything else.
bool parse_on_off(const std::string& flag, const std::string& text);
// --shadow-map-size: texels within RenderSettings' range, or "auto": the power of two at least
// the image's longer edge, 256 .. 2048. A map fitted to the view then spends about a texel per
// pixel, so shadows look alike at every image size and a thumbnail does not pay for a map many
// times its size.
int parse_shadow_map_size(const std::string& text, ImageSize image);
// --shadow-cascades: 1 .. RenderSettings::kMaxShadowCascades, or "auto":
// RenderSettings::kAutoShadowCascades, the count chosen each frame from the view.
int parse_shadow_cascades(const std::string& text);
// --tile-size: 16, 32, 64 or 128 pixels, or "auto": RenderSettings::kAutoTileSize, the size
// chosen each frame.
int parse_tile_size(const std::string& text);
// --tile-size's help.
inline constexpr const char* kTileSizeHelp =
    "Tile edge in pixels: 16, 32, 64 or 128, or auto: 128 where the tiles hold 8-bit codes (one "
    "sample, every model writing display values: the glmark2 scenes, the debug models), else 64. "
    "The image is the same at every size";

}  // namespace facet::cli
