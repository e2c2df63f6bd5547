// 16-bit grayscale PNGs (see png16_file.hpp).
#include "png16_file.hpp"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "facet/error.hpp"

namespace facet::cli {
namespace {

// libpng's default handlers print a line of their own before facet's error: these keep the
// message (or the errno of a failed fwrite) for facet's one line instead.
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

}  // namespace

void write_png16(std::FILE* file, const std::string& name, int width, int height,
                 const std::vector<std::uint16_t>& values) {
  // PNG stores 16-bit samples most significant byte first.
  std::vector<png_byte> bytes(values.size() * 2);
  for (std::size_t i = 0; i < values.size(); ++i) {
    bytes[2 * i] = static_cast<png_byte>(values[i] >> 8);
    bytes[2 * i + 1] = static_cast<png_byte>(values[i] & 0xff);
  }
  std::vector<png_bytep> rows(height);
  for (int y = 0; y < height; ++y) rows[y] = bytes.data() + static_cast<std::size_t>(y) * width * 2;

  PngFailure failure;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &failure, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw Error(name + ": cannot start the PNG encoder (out of memory)");
  }
  errno = 0;
  // libpng reports errors by longjmp; nothing with a destructor is created past this point.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error(
        name + ": write failed (" +
        (failure.error_number != 0 ? std::strerror(failure.error_number) : failure.message) + ")");
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, width, height, 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

}  // namespace facet::cli
