// What `facet render --outputs` writes for one frame: the outputs asked for, the file each goes
// to (decided by the -o name's extension), and writing them. A frame's files are written to
// temporary names in their folder and renamed into place only once all are complete, so a
// failure leaves none of them, and a file that exists under its own name is always whole.
#pragma once

#include <string>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/scene.hpp"

namespace facet::cli {

// Images a frame can write (the names --outputs takes).
enum class Output {
  color,        // the shaded image
  depth,        // view depth: distance along the camera's axis, scene units
  distance,     // distance from the eye along the pixel's ray, scene units
  normal,       // unit shading normal, world or camera space (--normal-space)
  instance,     // scene node index + 1, 0 where nothing was drawn
  triangle,     // triangle index in its mesh + 1, 0 where nothing was drawn
  barycentric,  // perspective-correct weights of the triangle's three vertices
  albedo,       // linear RGBA, unlit
};

// The -o name's extension: how outputs are stored.
enum class Container {
  png,  // color: 8-bit sRGB PNG; float outputs: OpenEXR; ids: 16-bit grayscale PNG
  ppm,  // as png, but color as binary PPM (P6)
  exr,  // every output OpenEXR: color linear float RGBA, ids 32-bit unsigned
  npy,  // one NumPy .npy per output
  npz,  // one NumPy .npz holding an array per output, named by it
};

const std::vector<std::string>& output_names();

struct OutputPlan {
  std::vector<Output> outputs{Output::color};  // in the order asked, no repeats
  NormalSpace normal_space = NormalSpace::world;
  Container container = Container::png;

  ExtraOutputs extra_outputs() const;
  // rgba32f when color goes to an EXR (linear float), else rgba8_srgb.
  ColorFormat color_format() const;
  // The files a frame named `path` writes, in the order of `outputs`: color to `path` itself,
  // each other output NAME beside it as STEM.NAME.EXT (EXT: .exr for floats, .png for ids
  // under .png/.ppm, else the container's), everything to `path` for an .npz.
  std::vector<std::string> files(const std::string& path) const;
};

// --outputs (comma-separated names) and --normal-space for output files named like `path`.
// Throws facet::Error naming the flag, or the path for an unknown extension.
OutputPlan plan_outputs(const std::string& outputs, const std::string& normal_space,
                        const std::string& path);

// Throws facet::Error naming `path` if no file can be written there: the path is a folder, its
// folder does not exist or is not writable, or (if `replacing`) it is an existing file that
// is not writable.
void check_output_path(const std::string& path, bool replacing);

// Throws facet::Error naming --outputs if the plan writes ids to a 16-bit PNG and the scene
// has ids beyond 65535 (more nodes, or a mesh with more triangles), before a frame is drawn.
void check_ids_fit(const OutputPlan& plan, const Scene& scene);

// Writes the frame's files (plan.files(path)). Throws facet::Error naming the file at fault
// (for example an id above 65535 bound for a 16-bit PNG), and then none of them is written.
void write_outputs(const Framebuffer& framebuffer, const OutputPlan& plan, const std::string& path);

}  // namespace facet::cli
