// Loading the program's modules (see modules.hpp).
#include "modules.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "facet/error.hpp"
#include "render_backend.hpp"

#if !FACET_MODULES_BUILT_IN
#include <dlfcn.h>
#endif

namespace facet::cli {
namespace {

#if !FACET_MODULES_BUILT_IN

// `symbol` of module `name` (loaded once), which `command` needs.
void* module_symbol(const std::string& name, const char* symbol, const std::string& command) {
  static std::mutex mutex;
  static std::map<std::string, void*> loaded;
  const std::lock_guard lock(mutex);
  void*& handle = loaded[name];
  if (handle == nullptr) {
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe");
    const std::string file = name + ".so";
    const std::filesystem::path beside = program.parent_path() / file;
    const std::filesystem::path installed =
        (program.parent_path() / FACET_MODULE_DIR / file).lexically_normal();
    const std::filesystem::path& path = std::filesystem::exists(beside) ? beside : installed;
    if (!std::filesystem::exists(path)) {
      throw Error(command + " needs the module " + file + ", which is not installed (not in " +
                  beside.parent_path().string() + " nor " + installed.parent_path().string() + ")");
    }
    handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
      throw Error(command + ": cannot load " + path.string() + ": " + dlerror());
  }
  void* entry = dlsym(handle, symbol);
  if (entry == nullptr) {
    throw Error(command + ": the module " + name + ".so has no " + symbol +
                " (is it from another facet build?)");
  }
  return entry;
}

template <class Function>
Function* module_entry(const std::string& name, const char* symbol, const std::string& command) {
  return reinterpret_cast<Function*>(module_symbol(name, symbol, command));
}

#endif  // !FACET_MODULES_BUILT_IN

}  // namespace

int run_view_module(const ViewOptions& options, const ViewArguments& arguments) {
#if FACET_MODULES_BUILT_IN
  return facet_view_run(options, arguments);
#else
  return module_entry<decltype(facet_view_run)>("facet-view", "facet_view_run", "facet view")(
      options, arguments);
#endif
}

std::unique_ptr<GlBackend> make_gl_backend(const RenderSettings& settings) {
#if !FACET_HAS_GL
  (void)settings;
  throw Error("--backend gl: this facet was built without the OpenGL backend (FACET_BUILD_GL=OFF)");
#elif FACET_MODULES_BUILT_IN
  return std::unique_ptr<GlBackend>(facet_gl_backend_new(settings));
#else
  return std::unique_ptr<GlBackend>(module_entry<decltype(facet_gl_backend_new)>(
      "facet-gl", "facet_gl_backend_new", "--backend gl")(settings));
#endif
}

}  // namespace facet::cli
