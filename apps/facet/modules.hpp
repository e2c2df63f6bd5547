// The program's parts that need a desktop's libraries are modules of their own, loaded by the
// commands that use them: `facet view` (view/: SDL2's window, OpenAL's sound; facet-view.so) and
// the OpenGL twin (gl/: EGL and OpenGL; facet-gl.so, for --backend gl and the viewer's B key).
// Every other command starts without loading those libraries, and the dozens they load in
// turn, and runs where they are not installed, as on a headless server.
//
// Found next to the program (the build tree), else in the library folder's facet/ (installed:
// lib/facet/ beside lib/libfacet.so). Builds with static libraries link both modules in: a
// module would carry a second copy of the library.
#pragma once

#include "facet/renderer.hpp"

namespace facet::cli {

struct ViewOptions;
struct ViewArguments;
class GlBackend;

// facet_view_run in the view module, with the flags and their checked values. Throws
// facet::Error, one line, when it cannot be loaded. (The OpenGL module's entry is called by
// make_gl_backend, render_backend.hpp.)
int run_view_module(const ViewOptions& options, const ViewArguments& arguments);

}  // namespace facet::cli

// The modules' entry points, found by these names in a shared build.
extern "C" {
int facet_view_run(const facet::cli::ViewOptions& options,
                   const facet::cli::ViewArguments& arguments);                      // view/
facet::cli::GlBackend* facet_gl_backend_new(const facet::RenderSettings& settings);  // gl/
}
