// Stage: output, how the resolves write the rows of tiles where nothing was drawn into the
// framebuffer. A framebuffer drawn into frame after frame (the viewer, a frame sequence,
// `facet bench`) already holds last frame's clear there. While an image fits in the caches,
// reading a row to compare costs less than writing it, which must fetch it first (and write it
// back later): a cleared row is written only where it differs. A larger one is read from memory
// either way: its cleared rows are written around the caches, with streaming (non-temporal)
// stores, which fetch nothing.
#pragma once

#include <cstddef>

namespace facet::pipeline {

// Images (the 8-bit color, the depth) of at least this many bytes take their cleared rows with
// streaming stores: 1920x1080 in 8-bit color (8.3 MB) gains, 1600x900 (5.8 MB) does not
// (BENCHMARKS.md §2). Where the target has no streaming stores, none does.
inline constexpr std::size_t kStreamedImageBytes = std::size_t{6} << 20;
bool streams_cleared_rows(std::size_t image_bytes);

// Writes `bytes` bytes (a whole number of 4-byte values) of a row of the clear color or depth to
// `out`: with streaming stores where `streaming`, which end_streamed_rows() must then order before
// another thread reads them; else only where `out` differs.
void write_cleared_row(void* out, const void* row, std::size_t bytes, bool streaming);
// Orders the streaming stores before whatever follows (a tile's rows before the frame ends).
void end_streamed_rows();

}  // namespace facet::pipeline
