// Output file readers for tests (see output_readers.hpp).
#include "support/output_readers.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <png.h>
#include <zlib.h>

#include <fstream>
#include <iterator>
#include <stdexcept>

namespace facet::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::uint32_t le(const std::string& bytes, std::size_t at, int size) {
  if (at + size > bytes.size()) throw std::runtime_error("read past the end");
  std::uint32_t v = 0;
  for (int i = size - 1; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

// The text between `key`'s quotes and the next ',' or '}' (or the tuple) in a .npy dict.
std::string dict_value(const std::string& dict, const std::string& key, const std::string& name) {
  std::size_t at = dict.find("'" + key + "':");
  if (at == std::string::npos) throw std::runtime_error(name + ": no '" + key + "' in " + dict);
  at = dict.find_first_not_of(' ', at + key.size() + 3);
  std::size_t end = dict[at] == '(' ? dict.find(')', at) + 1 : dict.find_first_of(",}", at);
  return dict.substr(at, end - at);
}

// numpy.lib.format version 1.0: magic, version, little-endian header length, dict, values.
NpyArray parse_npy(const std::string& bytes, const std::string& name) {
  if (bytes.compare(0, 6, "\x93NUMPY") != 0) throw std::runtime_error(name + ": not .npy");
  if (bytes[6] != 1 || bytes[7] != 0) throw std::runtime_error(name + ": not version 1.0");
  std::size_t header_length = le(bytes, 8, 2);
  std::string dict = bytes.substr(10, header_length);
  if (dict.empty() || dict.back() != '\n') throw std::runtime_error(name + ": header not ended");
  NpyArray array;
  std::string descr = dict_value(dict, "descr", name);
  array.dtype = descr.substr(1, descr.size() - 2);
  array.fortran_order = dict_value(dict, "fortran_order", name) == "True";
  std::string shape = dict_value(dict, "shape", name);
  for (std::size_t at = 1; at < shape.size();) {
    std::size_t end = shape.find_first_of(",)", at);
    std::string number = shape.substr(at, end - at);
    if (number.find_first_not_of(' ') != std::string::npos)
      array.shape.push_back(std::stoul(number));
    at = end + 1;
  }
  array.data_offset = 10 + header_length;
  array.data = bytes.substr(array.data_offset);
  return array;
}

}  // namespace

NpyArray read_npy(const std::string& path) { return parse_npy(slurp(path), path); }

// A zip (PKWARE APPNOTE 4.3.7): local headers with stored members, then the central directory.
std::vector<std::pair<std::string, NpyArray>> read_npz(const std::string& path) {
  std::string bytes = slurp(path);
  std::vector<std::pair<std::string, NpyArray>> members;
  std::size_t at = 0;
  while (le(bytes, at, 4) == 0x04034b50) {
    if (le(bytes, at + 8, 2) != 0) throw std::runtime_error(path + ": a member is compressed");
    std::uint32_t crc = le(bytes, at + 14, 4);
    std::uint32_t size = le(bytes, at + 18, 4);
    if (le(bytes, at + 22, 4) != size) throw std::runtime_error(path + ": sizes differ");
    std::size_t name_length = le(bytes, at + 26, 2), extra_length = le(bytes, at + 28, 2);
    std::string name = bytes.substr(at + 30, name_length);
    std::string data = bytes.substr(at + 30 + name_length + extra_length, size);
    if (data.size() != size) throw std::runtime_error(path + ": " + name + " is cut short");
    auto actual = crc32(0, reinterpret_cast<const Bytef*>(data.data()), data.size());
    if (actual != crc) throw std::runtime_error(path + ": " + name + ": CRC-32 does not match");
    if (name.size() < 4 || name.substr(name.size() - 4) != ".npy")
      throw std::runtime_error(path + ": member " + name + " is not .npy");
    members.emplace_back(name.substr(0, name.size() - 4), parse_npy(data, name));
    at += 30 + name_length + extra_length + size;
  }
  // The central directory lists the same members; its end record counts them.
  std::size_t end = bytes.rfind(std::string("PK\x05\x06", 4));
  if (end == std::string::npos || le(bytes, at, 4) != 0x02014b50)
    throw std::runtime_error(path + ": no central directory");
  if (le(bytes, end + 10, 2) != members.size() || le(bytes, end + 16, 4) != at)
    throw std::runtime_error(path + ": the end record does not match the members");
  return members;
}

ExrImage read_exr(const std::string& path) {
  Imf::InputFile file(path.c_str());
  const Imath::Box2i window = file.header().dataWindow();
  ExrImage image;
  image.width = window.max.x - window.min.x + 1;
  image.height = window.max.y - window.min.y + 1;
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  Imf::FrameBuffer frame;
  const auto& channels = file.header().channels();
  for (auto it = channels.begin(); it != channels.end(); ++it) {
    char* base = nullptr;
    if (it.channel().type == Imf::FLOAT) {
      image.floats[it.name()].resize(pixels);
      base = reinterpret_cast<char*>(image.floats[it.name()].data());
    } else if (it.channel().type == Imf::UINT) {
      image.uints[it.name()].resize(pixels);
      base = reinterpret_cast<char*>(image.uints[it.name()].data());
    } else {
      throw std::runtime_error(path + ": channel " + it.name() + " is half float");
    }
    frame.insert(it.name(), Imf::Slice(it.channel().type, base, 4, 4 * image.width));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  return image;
}

Gray16Image read_png16(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw std::runtime_error(path + ": cannot open");
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  Gray16Image image;
  std::vector<png_bytep> rows;
  std::vector<png_byte> bytes;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(file);
    throw std::runtime_error(path + ": cannot read PNG");
  }
  png_init_io(png, file);
  png_read_info(png, info);
  bool gray16 =
      png_get_bit_depth(png, info) == 16 && png_get_color_type(png, info) == PNG_COLOR_TYPE_GRAY;
  image.width = static_cast<int>(png_get_image_width(png, info));
  image.height = static_cast<int>(png_get_image_height(png, info));
  if (gray16) {
    bytes.resize(static_cast<std::size_t>(image.width) * image.height * 2);
    for (int y = 0; y < image.height; ++y) rows.push_back(bytes.data() + y * image.width * 2);
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(file);
  if (!gray16) throw std::runtime_error(path + ": not a 16-bit grayscale PNG");
  for (std::size_t i = 0; i < bytes.size(); i += 2)
    image.values.push_back(static_cast<std::uint16_t>(bytes[i] << 8 | bytes[i + 1]));  // MSB first
  return image;
}

}  // namespace facet::test
