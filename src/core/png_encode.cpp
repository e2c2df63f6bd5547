// PNG encoding (https://www.w3.org/TR/png-3/) for the rendered image, the last step of every
// thumbnail, so it is made fast:
// - each row is filtered by its left neighbour (SUB) instead of trying all five filters per
//   row, and compressed with zlib's run-length strategy (Z_RLE, no match search); rendered
//   images come out no bigger than with libpng's filter search;
// - the rows are compressed in bands of kBandRows, each band on whichever core is free. A band
//   ends with a sync flush (an empty stored block: byte-aligned and not final), so the bands'
//   raw deflate streams join into one zlib stream, as pigz joins them, and their Adler-32 sums
//   combine. Z_RLE only ever refers to the byte before, so a band that starts without the
//   previous band's history loses a few bytes at most. Band boundaries do not depend on the
//   thread count, so neither do the bytes.
// libpng compresses on one thread and takes no compressed data, so the four chunks around the
// data are written here (each is a length, a type, the data and a CRC-32).
#include "core/png_encode.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstddef>

#include "core/parallel.hpp"
#include "facet/error.hpp"

namespace facet::io {
namespace {

constexpr int kBandRows = 64;
// IDAT chunks of at most this many bytes (a chunk's length must stay below 2^31).
constexpr std::size_t kMaxIdatBytes = std::size_t{1} << 20;

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<std::uint8_t>(value >> shift));
}

void put_chunk(std::vector<std::uint8_t>& out, const char (&type)[5], const std::uint8_t* data,
               std::size_t size) {
  put_u32(out, static_cast<std::uint32_t>(size));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  put_u32(out,
          static_cast<std::uint32_t>(crc32(0, out.data() + start, static_cast<uInt>(size + 4))));
}

struct Band {
  std::vector<std::uint8_t> deflated;  // raw deflate data, ending in a sync flush or, last, final
  std::uint32_t adler = 1;             // Adler-32 of the filtered rows
  std::size_t filtered_size = 0;
};

// Rows [y0, y1) filtered with SUB (a filter-type byte, then each byte minus the same channel of
// the pixel to its left) and deflated.
Band compress_band(const std::uint8_t* rgba, int width, int y0, int y1, int channels, bool last) {
  const std::size_t row_bytes = 1 + static_cast<std::size_t>(width) * channels;
  std::vector<std::uint8_t> filtered(row_bytes * static_cast<std::size_t>(y1 - y0));
  for (int y = y0; y < y1; ++y) {
    const std::uint8_t* src = rgba + static_cast<std::size_t>(y) * width * 4;
    std::uint8_t* dst = filtered.data() + static_cast<std::size_t>(y - y0) * row_bytes;
    *dst++ = 1;  // SUB
    for (int c = 0; c < channels; ++c) dst[c] = src[c];
    for (int x = 1; x < width; ++x) {
      for (int c = 0; c < channels; ++c)
        dst[x * channels + c] = static_cast<std::uint8_t>(src[x * 4 + c] - src[(x - 1) * 4 + c]);
    }
  }
  Band band;
  band.filtered_size = filtered.size();
  band.adler = static_cast<std::uint32_t>(
      adler32(adler32(0, nullptr, 0), filtered.data(), static_cast<uInt>(filtered.size())));

  z_stream stream{};
  // A raw stream (negative window bits): the zlib header and checksum are the whole image's.
  if (deflateInit2(&stream, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -15, 8, Z_RLE) != Z_OK)
    throw Error("PNG encoder: cannot start zlib (out of memory)");
  band.deflated.resize(deflateBound(&stream, filtered.size()) + 16);
  stream.next_in = filtered.data();
  stream.avail_in = static_cast<uInt>(filtered.size());
  stream.next_out = band.deflated.data();
  stream.avail_out = static_cast<uInt>(band.deflated.size());
  const int result = deflate(&stream, last ? Z_FINISH : Z_SYNC_FLUSH);
  const bool complete = last ? result == Z_STREAM_END : result == Z_OK && stream.avail_out > 0;
  band.deflated.resize(stream.total_out);
  deflateEnd(&stream);
  if (!complete || stream.avail_in != 0) throw Error("PNG encoder: zlib failed");
  return band;
}

bool opaque(const std::uint8_t* rgba, std::size_t pixels) {
  for (std::size_t i = 0; i < pixels; ++i) {
    if (rgba[i * 4 + 3] != 255) return false;
  }
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const std::uint8_t* rgba, int width, int height) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  const int channels = opaque(rgba, pixels) ? 3 : 4;
  const int band_count = (height + kBandRows - 1) / kBandRows;
  std::vector<Band> bands(band_count);
  parallel_tasks(band_count, default_workers(), [&](int b, int) {
    const int y0 = b * kBandRows, y1 = std::min(height, y0 + kBandRows);
    bands[b] = compress_band(rgba, width, y0, y1, channels, b == band_count - 1);
  });

  // The zlib stream: header (deflate, 32 KiB window, default level), the bands, Adler-32.
  std::vector<std::uint8_t> data = {0x78, 0x9c};
  std::uint32_t adler = static_cast<std::uint32_t>(adler32(0, nullptr, 0));
  for (const Band& band : bands) {
    data.insert(data.end(), band.deflated.begin(), band.deflated.end());
    adler = static_cast<std::uint32_t>(
        adler32_combine(adler, band.adler, static_cast<z_off_t>(band.filtered_size)));
  }
  put_u32(data, adler);

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> header;
  put_u32(header, static_cast<std::uint32_t>(width));
  put_u32(header, static_cast<std::uint32_t>(height));
  // 8 bits per channel; color type 2 (RGB) or 6 (RGBA); deflate, adaptive filters, no interlace.
  header.insert(header.end(), {8, static_cast<std::uint8_t>(channels == 3 ? 2 : 6), 0, 0, 0});
  put_chunk(png, "IHDR", header.data(), header.size());
  const std::uint8_t perceptual_intent = 0;
  put_chunk(png, "sRGB", &perceptual_intent, 1);
  for (std::size_t at = 0; at < data.size(); at += kMaxIdatBytes)
    put_chunk(png, "IDAT", data.data() + at, std::min(kMaxIdatBytes, data.size() - at));
  put_chunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace facet::io
