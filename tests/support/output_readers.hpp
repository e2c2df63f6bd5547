// Readers for the files `facet render --outputs` writes, written from the formats' own
// descriptions rather than from facet's writers, so that the tests check the files: NumPy .npy
// and .npz (each member's CRC-32 checked), OpenEXR (through the OpenEXR library) and 16-bit
// grayscale PNG (through libpng). Each throws std::runtime_error on a malformed file.
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace facet::test {

struct NpyArray {
  std::string dtype;  // "descr": "<f4", "<u4", "|u1"
  bool fortran_order = true;
  std::vector<std::size_t> shape;
  std::size_t data_offset = 0;  // where the values start in the file
  std::string data;             // the values' bytes

  template <class T>
  std::vector<T> values() const {
    std::vector<T> out(data.size() / sizeof(T));
    std::memcpy(out.data(), data.data(), out.size() * sizeof(T));
    return out;
  }
};

NpyArray read_npy(const std::string& path);
// The members of an .npz by name, without ".npy", in the order stored.
std::vector<std::pair<std::string, NpyArray>> read_npz(const std::string& path);

struct ExrImage {
  int width = 0;
  int height = 0;
  std::map<std::string, std::vector<float>> floats;         // FLOAT channels by name
  std::map<std::string, std::vector<std::uint32_t>> uints;  // UINT channels by name
};
ExrImage read_exr(const std::string& path);

struct Gray16Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> values;
};
// Fails unless the PNG is 16-bit grayscale.
Gray16Image read_png16(const std::string& path);

}  // namespace facet::test
