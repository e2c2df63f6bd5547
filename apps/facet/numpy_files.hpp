// Writing NumPy files: .npy (format version 1.0: a header naming the type and shape, then the
// values in C order) and .npz (a zip of .npy files, stored uncompressed, as numpy.savez
// writes), so `numpy.load` reads facet's outputs directly.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace facet::cli {

struct NumpyArray {
  std::string name;                // the array's name in an .npz (its member is NAME.npy)
  std::string dtype;               // NumPy's type string: "|u1", "<f4", "<u4"
  std::vector<std::size_t> shape;  // e.g. {height, width, 4}
  const void* data = nullptr;      // the values, C order, little-endian
  std::size_t bytes = 0;           // of data
};

// Write to an open file; write errors show in std::ferror(file). write_npz throws
// facet::Error naming `name` if the arrays pass the 4 GiB a zip without ZIP64 can hold.
void write_npy(std::FILE* file, const NumpyArray& array);
void write_npz(std::FILE* file, const std::vector<NumpyArray>& arrays, const std::string& name);

}  // namespace facet::cli
