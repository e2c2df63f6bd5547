// libFuzzer target for facet's PGM/PPM reader (src/io/pnm.cpp): any input must either parse
// into a consistent image or throw facet::Error; a crash, a sanitizer report or an image
// whose buffer does not match its size is a bug.
//   clang++ -std=c++20 -g -O1 -fsanitize=fuzzer,address -Iinclude -Isrc \
//     tests/fuzz/pnm_fuzz.cpp src/io/pnm.cpp -o pnm_fuzz && ./pnm_fuzz tests/fuzz/corpus/pnm
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/pnm.hpp"
#include "facet/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const facet::io::PnmImage image = facet::io::parse_pnm(data, size, "fuzz.pnm");
    const bool size_ok =
        image.width >= 1 && image.height >= 1 && image.width <= facet::io::kMaxPnmSize &&
        image.height <= facet::io::kMaxPnmSize &&
        image.rgba.size() == static_cast<std::size_t>(image.width) * image.height * 4;
    if (!size_ok) __builtin_trap();
  } catch (const facet::Error&) {
    // Malformed input: the expected outcome for most fuzz inputs.
  }
  return 0;
}
