// Writing rendered images: PNG through libpng, PPM (P6) by hand. Both go to a temporary file
// beside the target that is renamed into place only after a complete, checked write.
#include <png.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/color.hpp"
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

// The framebuffer as 8-bit sRGB RGBA rows.
std::vector<std::uint8_t> to_rgba8(const Framebuffer& fb) {
  if (fb.format() == ColorFormat::rgba8_srgb) return fb.rgba8();
  const auto& f = fb.rgba32f();
  std::vector<std::uint8_t> out(f.size());
  for (std::size_t i = 0; i < f.size(); i += 4) {
    for (int c = 0; c < 3; ++c) out[i + c] = shading::encode_srgb8(f[i + c]);
    out[i + 3] = shading::encode_unorm8(f[i + 3]);
  }
  return out;
}

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f) std::fclose(f);
  }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors through these instead of printing its own line to stderr and then
// aborting: the message (or, for a failed fwrite, the errno behind it) becomes facet's one error
// line. A write facet makes has nothing to warn about, so warnings are dropped.
struct PngFailure {
  int error_number = 0;
  char message[160] = {};
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* failure = static_cast<PngFailure*>(png_get_error_ptr(png));
  failure->error_number = errno;  // libpng's write callback calls this right after fwrite
  std::snprintf(failure->message, sizeof failure->message, "%s", message ? message : "");
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

void write_png(std::FILE* file, const Framebuffer& fb, const std::vector<std::uint8_t>& rgba,
               const std::string& path) {
  PngFailure failure;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &failure, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw Error(path + ": cannot start PNG encoder (out of memory)");
  }
  std::vector<png_bytep> rows(fb.height());
  for (int y = 0; y < fb.height(); ++y) {
    rows[y] = const_cast<png_bytep>(rgba.data() + static_cast<std::size_t>(y) * fb.width() * 4);
  }
  errno = 0;
  // libpng reports errors by longjmp; nothing with a destructor is created past this point.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error(
        path + ": write failed (" +
        (failure.error_number != 0 ? std::strerror(failure.error_number) : failure.message) + ")");
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, fb.width(), fb.height(), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  // Thumbnails and frame sequences care about time. Each row filtered by its left neighbour
  // (SUB) instead of libpng trying all five filters per row, and zlib's run-length strategy
  // (Z_RLE, which needs no match search): much faster to write than trying every filter, and
  // rendered frames come out no bigger.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_strategy(png, Z_RLE);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
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
