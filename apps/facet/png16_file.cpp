// 16-bit grayscale PNGs (see png16_file.hpp).
#include "png16_file.hpp"

#include <png.h>

#include "facet/error.hpp"

namespace facet::cli {

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

  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw Error(name + ": cannot start the PNG encoder (out of memory)");
  }
  // libpng reports errors by longjmp; nothing with a destructor is created past this point.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error(name + ": PNG write failed");
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
