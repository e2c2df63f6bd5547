// facet: a CPU software rasterizer. Include this one header for the whole public API.
// Start with facet::Renderer (renderer.hpp) and the meshes in procedural.hpp.
#pragma once

#include "facet/camera.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/import.hpp"
#include "facet/islands.hpp"
#include "facet/light.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/overlay.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/sound.hpp"
#include "facet/teapot.hpp"
#include "facet/texture.hpp"
