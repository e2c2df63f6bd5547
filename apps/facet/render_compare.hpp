// `facet render --compare A,B,...`: one view drawn once per variant — a shading model given to
// every material (flat, gouraud, phong, ...), a backend (facet, gl) or a tone mapping (none,
// pbr-neutral, aces) — and the images laid side by side, left to right in the order given, each
// labelled with its name: the comparison the course write-ups on shading show, in one picture.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/material.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "render_backend.hpp"

namespace facet::cli {

struct CompareVariant {
  std::string name;        // as given: the panel's label
  bool shaded_as = false;  // every material gets `shading`
  ShadingModel shading{};
  Backend backend = Backend::facet;
  std::optional<ToneMapping> tone_mapping;  // instead of the settings'
};

// The variants of a --compare list: shading model, backend and tone mapping names, separated
// by commas; a variant that names a model is drawn by `backend`. Throws facet::Error naming
// --compare for an unknown name, a repeat, or fewer than two.
std::vector<CompareVariant> parse_compare(const std::string& list, Backend backend);

// Draws each variant of `scene` seen by `camera` as a size.width x size.height panel with
// `settings`, and returns them side by side with their labels (rgba8 sRGB, no depth).
// Throws facet::Error naming --compare when the picture would be wider than 8192 pixels.
Framebuffer render_comparison(const std::vector<CompareVariant>& variants, const Scene& scene,
                              const Camera& camera, ImageSize size, const RenderSettings& settings);

}  // namespace facet::cli
