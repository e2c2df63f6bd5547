// facet: a CPU software rasterizer. This header is the core (facet::core): meshes, materials,
// lights, cameras, scenes, textures, the renderer and image files. Start with facet::Renderer
// (renderer.hpp). The other layers are included by name: facet/import.hpp (model files),
// facet/worlds.hpp (the built-in worlds and procedural meshes), facet/sound.hpp (OpenAL sound).
#pragma once

#include "facet/camera.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/light.hpp"
#include "facet/material.hpp"
#include "facet/mesh.hpp"
#include "facet/mesh_tools.hpp"
#include "facet/overlay.hpp"
#include "facet/render_texture.hpp"
#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/texture.hpp"
#include "facet/version.hpp"
