// Output files of a frame (see output_files.hpp): names, formats and the all-or-nothing write.
#include "output_files.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "arguments.hpp"
#include "exr_file.hpp"
#include "facet/error.hpp"
#include "facet/image_io.hpp"
#include "numpy_files.hpp"
#include "png16_file.hpp"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

const char* name_of(Output output) { return output_names()[static_cast<int>(output)].c_str(); }

bool is_id(Output output) { return output == Output::instance || output == Output::triangle; }

// Where the extension starts in a path (after its last '/'), or npos.
std::size_t extension_at(const std::string& path) {
  std::size_t slash = path.rfind('/');
  std::size_t dot = path.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string::npos;
  if (dot == (slash == std::string::npos ? 0 : slash + 1)) return std::string::npos;  // ".png"
  return dot;
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

Container container_of(const std::string& path) {
  // Said first: a folder's name has no extension either.
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error(path + ": is a directory");
  std::size_t at = extension_at(path);
  std::string extension = at == std::string::npos ? "" : lower(path.substr(at));
  if (extension == ".png") return Container::png;
  if (extension == ".ppm") return Container::ppm;
  if (extension == ".exr") return Container::exr;
  if (extension == ".npy") return Container::npy;
  if (extension == ".npz") return Container::npz;
  std::string what = extension.empty() ? "has no extension to tell the output type"
                                       : "unknown output type '" + extension + "'";
  throw Error(path + ": " + what + " (use .png, .ppm, .exr, .npy or .npz)");
}

// The extension of the file an output other than color goes to.
const char* extension_for(Container container, Output output) {
  switch (container) {
    case Container::png:
    case Container::ppm:
      return is_id(output) ? ".png" : ".exr";
    case Container::exr:
      return ".exr";
    case Container::npy:
      return ".npy";
    case Container::npz:
      return ".npz";
  }
  return "";
}

enum class ValueType { u8, f32, u32 };

// An output's values in the framebuffer: `channels` values of `type` per pixel.
struct Values {
  const void* data;
  int channels;
  ValueType type;
};

Values values_of(const Framebuffer& fb, Output output) {
  switch (output) {
    case Output::color:
      if (fb.format() == ColorFormat::rgba32f) return {fb.rgba32f().data(), 4, ValueType::f32};
      return {fb.rgba8().data(), 4, ValueType::u8};
    case Output::depth:
      return {fb.view_depth().data(), 1, ValueType::f32};
    case Output::distance:
      return {fb.ray_distance().data(), 1, ValueType::f32};
    case Output::normal:
      return {fb.normals().data(), 3, ValueType::f32};
    case Output::instance:
      return {fb.instance_ids().data(), 1, ValueType::u32};
    case Output::triangle:
      return {fb.triangle_ids().data(), 1, ValueType::u32};
    case Output::barycentric:
      return {fb.barycentrics().data(), 3, ValueType::f32};
    case Output::albedo:
      return {fb.albedo().data(), 4, ValueType::f32};
  }
  return {nullptr, 0, ValueType::f32};
}

NumpyArray numpy_array(const Framebuffer& fb, Output output) {
  Values v = values_of(fb, output);
  NumpyArray array;
  array.name = name_of(output);
  array.dtype = v.type == ValueType::u8 ? "|u1" : v.type == ValueType::f32 ? "<f4" : "<u4";
  array.shape = {static_cast<std::size_t>(fb.height()), static_cast<std::size_t>(fb.width())};
  if (v.channels > 1) array.shape.push_back(static_cast<std::size_t>(v.channels));
  array.data = v.data;
  array.bytes = static_cast<std::size_t>(fb.width()) * fb.height() * v.channels *
                (v.type == ValueType::u8 ? 1 : 4);
  return array;
}

// Channel names: R, G, B (and A) for color, albedo and the three-value outputs, so any EXR
// viewer shows them; Z for the distances, as compositing tools name depth; "id" for the ids.
std::vector<ExrChannel> exr_channels(const Framebuffer& fb, Output output) {
  Values v = values_of(fb, output);
  const float* floats = static_cast<const float*>(v.data);
  if (v.type == ValueType::u32) return {{"id", v.data, true, 1}};
  if (v.channels == 1) return {{"Z", v.data, false, 1}};
  std::vector<ExrChannel> channels;
  const char* names[] = {"R", "G", "B", "A"};
  for (int c = 0; c < v.channels; ++c)
    channels.push_back({names[c], floats + c, false, v.channels});
  return channels;
}

// The ids as 16-bit values; throws if one does not fit.
std::vector<std::uint16_t> ids16(const Framebuffer& fb, Output output, const std::string& name) {
  const std::vector<std::uint32_t>& ids =
      output == Output::instance ? fb.instance_ids() : fb.triangle_ids();
  std::vector<std::uint16_t> out(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] > 0xffff) {
      throw Error(name + ": " + name_of(output) + " id " + std::to_string(ids[i]) + " at pixel (" +
                  std::to_string(i % fb.width()) + ", " + std::to_string(i / fb.width()) +
                  ") does not fit a 16-bit PNG (at most 65535); name the output .exr, .npy or " +
                  ".npz, which hold 32-bit ids");
    }
    out[i] = static_cast<std::uint16_t>(ids[i]);
  }
  return out;
}

// Writes through a FILE opened on `temporary`, then checks that every byte reached the disk.
template <class Write>
void write_file(const std::string& temporary, const std::string& name, Write write) {
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) throw Error(name + ": cannot write (" + std::strerror(errno) + ")");
  try {
    write(file);
  } catch (...) {
    std::fclose(file);
    throw;
  }
  errno = 0;
  bool ok = std::fflush(file) == 0 && !std::ferror(file);
  int error_number = errno;
  if (std::fclose(file) != 0) {
    ok = false;
    if (error_number == 0) error_number = errno;
  }
  if (!ok) {
    throw Error(name + ": write failed (" +
                (error_number != 0 ? std::strerror(error_number) : "an I/O error") + ")");
  }
}

// The temporary name a file is written under: hidden, in the folder of the file it will replace
// (`target`, which is `name` or where the link `name` points), so the rename is atomic; with the
// process id (so two runs never share one) and the extension of `name` (which chose the format).
std::string temporary_name(const std::string& target, const std::string& name) {
  std::size_t slash = target.rfind('/');
  std::size_t name_at = slash == std::string::npos ? 0 : slash + 1;
  std::size_t dot = extension_at(target);
  std::size_t stem_end = dot == std::string::npos ? target.size() : dot;
  std::size_t name_dot = extension_at(name);
  return target.substr(0, name_at) + "." + target.substr(name_at, stem_end - name_at) + ".tmp-" +
         std::to_string(::getpid()) +
         (name_dot == std::string::npos ? std::string() : name.substr(name_dot));
}

void write_one(const Framebuffer& fb, const OutputPlan& plan, Output output,
               const std::string& temporary, const std::string& name) {
  if (plan.container == Container::npy) {
    NumpyArray array = numpy_array(fb, output);
    write_file(temporary, name, [&](std::FILE* f) { write_npy(f, array); });
  } else if (output == Output::color && plan.container != Container::exr) {
    const ImageFileType type =
        plan.container == Container::png ? ImageFileType::png : ImageFileType::ppm;
    write_file(temporary, name, [&](std::FILE* f) { write_image(fb, type, f, name); });
  } else if (is_id(output) && plan.container != Container::exr) {
    std::vector<std::uint16_t> ids = ids16(fb, output, name);
    write_file(temporary, name,
               [&](std::FILE* f) { write_png16(f, name, fb.width(), fb.height(), ids); });
  } else {
    write_exr(temporary, name, fb.width(), fb.height(), exr_channels(fb, output));
  }
}

}  // namespace

const std::vector<std::string>& output_names() {
  static const std::vector<std::string> names = {"color",    "depth",    "distance",    "normal",
                                                 "instance", "triangle", "barycentric", "albedo"};
  return names;
}

ExtraOutputs OutputPlan::extra_outputs() const {
  ExtraOutputs extra;
  for (Output output : outputs) {
    extra.view_depth |= output == Output::depth;
    extra.ray_distance |= output == Output::distance;
    if (output == Output::normal) extra.normals = normal_space;
    extra.instance_ids |= output == Output::instance;
    extra.triangle_ids |= output == Output::triangle;
    extra.barycentrics |= output == Output::barycentric;
    extra.albedo |= output == Output::albedo;
  }
  return extra;
}

ColorFormat OutputPlan::color_format() const {
  return container == Container::exr ? ColorFormat::rgba32f : ColorFormat::rgba8_srgb;
}

std::vector<std::string> OutputPlan::files(const std::string& path) const {
  if (container == Container::npz) return {path};
  std::string stem = path.substr(0, extension_at(path));
  std::vector<std::string> files;
  for (Output output : outputs) {
    if (output == Output::color) {
      files.push_back(path);
    } else {
      files.push_back(stem + "." + name_of(output) + extension_for(container, output));
    }
  }
  return files;
}

OutputPlan plan_outputs(const std::string& outputs, const std::string& normal_space,
                        const std::string& path) {
  OutputPlan plan;
  plan.outputs.clear();
  const std::vector<std::string>& names = output_names();
  std::size_t start = 0;
  while (true) {
    std::size_t end = outputs.find(',', start);
    std::string name = outputs.substr(start, end == std::string::npos ? end : end - start);
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) {
      throw Error("--outputs: " + (name.empty() ? "an empty name" : "'" + name + "'") +
                  " is not an output (" + joined(names) + ")");
    }
    Output output = static_cast<Output>(found - names.begin());
    if (std::find(plan.outputs.begin(), plan.outputs.end(), output) != plan.outputs.end()) {
      throw Error("--outputs: '" + name + "' is asked for twice");
    }
    plan.outputs.push_back(output);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  if (normal_space == "world") {
    plan.normal_space = NormalSpace::world;
  } else if (normal_space == "camera") {
    plan.normal_space = NormalSpace::camera;
  } else {
    throw Error("--normal-space: expected world or camera, got '" + normal_space + "'");
  }
  plan.container = container_of(path);
  return plan;
}

void check_output_path(const std::string& path, bool replacing) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error(path + ": is a directory");
  fs::path folder = fs::path(write_target(path)).parent_path();  // where the file is replaced
  if (folder.empty()) folder = ".";
  if (!fs::is_directory(folder, ec)) {
    throw Error(path + ": directory " + folder.string() + " does not exist");
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    throw Error(path + ": directory " + folder.string() + " is not writable");
  }
  if (replacing && fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0) {
    throw Error(path + ": file is not writable");
  }
}

void check_ids_fit(const OutputPlan& plan, const Scene& scene) {
  if (plan.container != Container::png && plan.container != Container::ppm) return;
  constexpr std::size_t kLargest = 0xffff;
  const std::string advice =
      ", more than a 16-bit PNG holds (65535); name the output .exr, .npy or .npz, which hold "
      "32-bit ids";
  for (Output output : plan.outputs) {
    if (output == Output::instance && scene.nodes.size() > kLargest) {
      throw Error("--outputs: instance ids of this scene go up to " +
                  std::to_string(scene.nodes.size()) + " (one per scene node)" + advice);
    }
    if (output != Output::triangle) continue;
    for (const auto& mesh : scene.meshes) {
      if (mesh->topology != Topology::lines && mesh->topology != Topology::points &&
          mesh->primitive_count() > kLargest) {
        throw Error("--outputs: triangle ids of this scene go up to " +
                    std::to_string(mesh->primitive_count()) + " (a mesh of that many triangles)" +
                    advice);
      }
    }
  }
}

void write_outputs(const Framebuffer& fb, const OutputPlan& plan, const std::string& path) {
  std::vector<std::string> files = plan.files(path);
  // A file name that is a symbolic link is written through: its target is replaced.
  std::vector<std::string> targets;
  for (const std::string& file : files) targets.push_back(write_target(file));
  std::vector<std::string> temporaries;
  try {
    if (plan.container == Container::npz) {
      std::vector<NumpyArray> arrays;
      for (Output output : plan.outputs) arrays.push_back(numpy_array(fb, output));
      temporaries.push_back(temporary_name(targets[0], path));
      write_file(temporaries.back(), path, [&](std::FILE* f) { write_npz(f, arrays, path); });
    } else {
      for (std::size_t i = 0; i < files.size(); ++i) {
        temporaries.push_back(temporary_name(targets[i], files[i]));
        write_one(fb, plan, plan.outputs[i], temporaries.back(), files[i]);
      }
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
      std::error_code ec;
      fs::rename(temporaries[i], targets[i], ec);
      if (ec) throw Error(files[i] + ": cannot rename into place (" + ec.message() + ")");
    }
  } catch (...) {
    for (const std::string& temporary : temporaries) std::remove(temporary.c_str());
    throw;
  }
}

}  // namespace facet::cli
