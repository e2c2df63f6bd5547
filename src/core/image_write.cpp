// Writing rendered images: PNG (png_encode.cpp) and PPM (P6). Both go to a temporary file
// beside the target that is renamed into place only after a complete, checked write.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/png_encode.hpp"
#include "core/simd_target.hpp"
#include "core/srgb_row.hpp"
#include "facet/error.hpp"
#include "facet/image_io.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The framebuffer as 8-bit sRGB RGBA rows: a float one encoded a row at a time by the encode
// kernel (core/srgb_row.hpp), each row first copied into glm::vec4s, the kernel's input.
std::vector<std::uint8_t> to_rgba8(const Framebuffer& fb) {
  if (!fb.has_color()) throw Error("image: a depth-only framebuffer has no color image to write");
  if (fb.format() == ColorFormat::rgba8_srgb) return fb.rgba8();
  const std::vector<float>& f = fb.rgba32f();
  std::vector<std::uint8_t> out(f.size());
  const shading::EncodeSrgbRowKernel encode = shading::encode_srgb_row_kernel(chosen_simd_target());
  const auto width = static_cast<std::size_t>(fb.width());
  std::vector<glm::vec4> row(width);
  for (std::size_t first = 0; first < f.size(); first += 4 * width) {
    std::memcpy(row.data(), &f[first], sizeof(glm::vec4) * width);
    encode(row.data(), fb.width(), 1.0f, &out[first]);
  }
  return out;
}

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f) std::fclose(f);
  }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

void write_png(std::FILE* file, const Framebuffer& fb, const std::vector<std::uint8_t>& rgba,
               const std::string& path) {
  const std::vector<std::uint8_t> png = io::encode_png(rgba.data(), fb.width(), fb.height());
  errno = 0;
  if (std::fwrite(png.data(), 1, png.size(), file) != png.size()) {
    throw Error(path + ": write failed (" + (errno != 0 ? std::strerror(errno) : "an I/O error") +
                ")");
  }
}

void write_ppm(std::FILE* file, const Framebuffer& fb, const std::vector<std::uint8_t>& rgba,
               const std::string& path) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(fb.width()) * fb.height() * 3);
  for (std::size_t i = 0, j = 0; i < rgba.size(); i += 4, j += 3) {
    rgb[j] = rgba[i], rgb[j + 1] = rgba[i + 1], rgb[j + 2] = rgba[i + 2];
  }
  errno = 0;
  if (std::fprintf(file, "P6\n%d %d\n255\n", fb.width(), fb.height()) < 0 ||
      std::fwrite(rgb.data(), 1, rgb.size(), file) != rgb.size()) {
    throw Error(path + ": write failed (" + (errno != 0 ? std::strerror(errno) : "an I/O error") +
                ")");
  }
}

}  // namespace

std::string write_target(const std::string& path) {
  constexpr int kMaxLinks = 40;  // Linux's MAXSYMLINKS: deeper means a loop
  fs::path target = path;
  for (int links = 0;; ++links) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(target, ec))) return target.string();
    if (links == kMaxLinks) throw Error(path + ": too many levels of symbolic links");
    fs::path next = fs::read_symlink(target, ec);
    if (ec) throw Error(path + ": cannot read the symbolic link (" + ec.message() + ")");
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
}

ImageFileType image_file_type(const std::string& path) {
  std::string ext = lower_extension(path);
  if (ext == ".png") return ImageFileType::png;
  if (ext == ".ppm") return ImageFileType::ppm;
  throw Error(path + ": unknown image type '" + ext + "' (use .png or .ppm)");
}

void check_writable(const std::string& path) {
  std::error_code is_directory_error;
  // Said first: a directory's name has no image extension either.
  if (fs::is_directory(path, is_directory_error)) throw Error(path + ": is a directory");
  image_file_type(path);
  const std::string target = write_target(path);
  fs::path dir = fs::path(target).parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw Error(path + ": directory " + dir.string() + " does not exist");
  if (fs::is_directory(target, ec)) throw Error(path + ": is a directory");
  if (::access(dir.c_str(), W_OK) != 0)
    throw Error(path + ": directory " + dir.string() + " is not writable");
  if (fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0)
    throw Error(path + ": file is not writable");
}

void write_image(const Framebuffer& framebuffer, ImageFileType type, std::FILE* file,
                 const std::string& name) {
  std::vector<std::uint8_t> rgba = to_rgba8(framebuffer);
  if (type == ImageFileType::png) {
    write_png(file, framebuffer, rgba, name);
  } else {
    write_ppm(file, framebuffer, rgba, name);
  }
}

void write_image(const Framebuffer& framebuffer, const std::string& path) {
  if (!framebuffer.has_color()) {
    throw Error(path + ": a depth-only framebuffer has no color image to write");
  }
  ImageFileType type = image_file_type(path);
  // Beside the file it replaces, so that the rename is atomic (same file system).
  const std::string target = write_target(path);
  std::string temporary = target + ".tmp-" + std::to_string(::getpid());
  {
    File file(std::fopen(temporary.c_str(), "wb"));
    if (!file) throw Error(path + ": cannot write (" + std::strerror(errno) + ")");
    try {
      write_image(framebuffer, type, file.get(), path);
    } catch (...) {
      file.reset();
      std::remove(temporary.c_str());
      throw;
    }
    errno = 0;
    bool ok = std::fflush(file.get()) == 0 && !std::ferror(file.get());
    int error_number = errno;
    if (std::fclose(file.release()) != 0) {
      ok = false;
      if (error_number == 0) error_number = errno;
    }
    if (!ok) {
      std::remove(temporary.c_str());
      throw Error(path + ": write failed (" +
                  (error_number != 0 ? std::strerror(error_number) : "an I/O error") + ")");
    }
  }
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw Error(path + ": cannot rename into place (" + ec.message() + ")");
  }
}

}  // namespace facet
