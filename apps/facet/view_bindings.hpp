// Every key and mouse binding of `facet view`, in one table: the F1 help panel lists it and the
// command's --help text is built from it, so the two cannot drift apart.
#pragma once

#include <string>

namespace facet::cli {

struct ViewBinding {
  const char* keys;
  const char* action;
};

inline constexpr ViewBinding kViewBindings[] = {
    {"W A S D", "move (orbit: W/S zoom, A/D orbit)"},
    {"Q E / Ctrl Space", "down / up"},
    {"arrows", "turn (orbit: orbit)"},
    {"Shift", "run (4x)"},
    {"mouse", "click to capture, then look; Esc releases"},
    {"left drag", "orbit: turn around the target"},
    {"middle drag", "orbit: pan"},
    {"wheel", "orbit: zoom"},
    {"Tab", "orbit <-> first person"},
    {"M", "mute / unmute sound"},
    {"B", "renderer: facet, its OpenGL twin, their difference (x8)"},
    {"T", "tone mapping: pbr-neutral, aces, none"},
    {"F1", "this help"},
    {"F2", "render mode: shaded, wireframe, wire overlay, depth, normals,"},
    {"", "overdraw heat map, tile bins"},
    {"F3 / F4", "field of view down / up"},
    {"F5 / F6", "render resolution down / up (320x180 ... 3840x2160)"},
    {"F7", "shading model (the materials' own, unlit ... pbr)"},
    {"F8", "threads: 1, 2, ... cores, all"},
    {"F9", "overlay on / off"},
    {"F10", "anti-aliasing (MSAA): 1, 2, 4, 8, 16 samples per pixel"},
    {"F11", "windowed / fullscreen"},
    {"F12", "save the frame (facet-screenshot-N.png)"},
    {"Shift+F12", "save the window, bars included (facet-window-N.png)"},
    {"Esc", "release the mouse; again: quit"},
};

// "W A S D: move ..." as one line per binding, for help texts.
inline std::string view_bindings_text(const char* indent) {
  std::string text;
  for (const ViewBinding& b : kViewBindings) {
    text += indent;
    text += b.keys;
    text += *b.keys ? ": " : "  ";  // a continued line has no keys
    text += b.action;
    text += "\n";
  }
  return text;
}

}  // namespace facet::cli
