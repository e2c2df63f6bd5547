// The built-in scenes by name (see facet/worlds.hpp).
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/worlds.hpp"

namespace facet {

std::vector<std::string> builtin_scene_names() { return {"shapes", "teapot", "islands"}; }

Scene make_builtin_scene(const std::string& name) {
  if (name == "shapes") return make_shapes_scene();
  if (name == "teapot") return make_teapot_scene();
  if (name == "islands") return make_islands_scene();
  std::string known;
  for (const auto& n : builtin_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown scene '" + name + "' (built-in scenes: " + known + ")");
}

}  // namespace facet
