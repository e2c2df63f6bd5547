// Where setup (setup.cpp) puts a geometry chunk's primitives: straight into the frame's
// triangle, plane, line and point arrays, which raster reads, so no merge copy follows the
// parallel set-up. geometry.cpp gives each chunk a region of each array sized for its primitives
// (one triangle per input triangle, three edges per triangle, one segment per line, one point
// per point); only
// clipping can set up more triangles than that, and those go to the chunk's overflow buffer,
// which geometry.cpp appends to the frame's arrays once every chunk is done.
#pragma once

#include <cassert>
#include <cstdint>

#include "pipeline/bin/bin.hpp"
#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Marks a chunk's sequence entry as an index into its overflow buffer until geometry.cpp
// rewrites it. Primitive indices stay below kMaxPrimitiveIndex (2^29): a frame of 2^29 set-up
// triangles would need over 50 GB for them.
inline constexpr std::uint32_t kOverflowBit = 0x40000000u;
static_assert(kMaxPrimitiveIndex <= kOverflowBit && !(kOverflowBit & (kLineBit | kPointBit)));

struct TriangleSlot {
  SetupTriangle* triangle;
  Plane* planes;              // `varyings` planes to fill
  std::uint32_t plane_index;  // what SetupTriangle::varying_planes must say
  std::uint32_t entry_index;  // what its sequence entry says
};

class PrimitiveSink {
 public:
  PrimitiveSink(Frame& frame, GeometryChunk& chunk, int varyings)
      : frame_(frame),
        triangles_(frame.triangles.data()),
        planes_(frame.planes.data()),
        lines_(frame.lines.data()),
        points_(frame.points.data()),
        sequence_(frame.sequence.data()),
        chunk_(chunk),
        varyings_(static_cast<std::uint32_t>(varyings)) {}

  const Frame& frame() const { return frame_; }

  // A place for the next triangle (and its varying planes), in submission order. `edges` is
  // the triangle being set up, with its edge functions and bounding box already final
  // (binning's tile tests read them). Always inline: setup calls it for every triangle, and
  // GCC would keep it out of line.
  [[gnu::always_inline]] TriangleSlot add_triangle(const SetupTriangle& edges) {
    const TriangleSlot slot = reserve_triangle();
    append(slot.entry_index, &edges, edges.min_x, edges.min_y, edges.max_x, edges.max_y);
    return slot;
  }

  // add_triangle in two steps, for a triangle set up in place (batched setup writes each field
  // straight into its slot): its slot, then, once its edge functions and bounding box are
  // written there, its sequence entry. A slot's planes stay valid until the next slot is
  // reserved.
  [[gnu::always_inline]] TriangleSlot reserve_triangle() {
    GeometryChunk::Region& r = chunk_.triangles;
    if (r.used < r.capacity) {
      const std::uint32_t index = r.begin + r.used;
      const std::uint32_t plane_index = chunk_.planes_begin + r.used * varyings_;
      ++r.used;
      return {triangles_ + index, planes_ + plane_index, plane_index, index};
    }
    PrimitiveBuffer& o = chunk_.overflow;
    const auto index = static_cast<std::uint32_t>(o.triangles.size());
    const auto plane_index = static_cast<std::uint32_t>(o.planes.size());
    o.triangles.emplace_back();
    o.planes.resize(plane_index + varyings_);
    return {&o.triangles.back(), o.planes.data() + plane_index, plane_index, index | kOverflowBit};
  }
  // How many planes may be written from slot.planes on: its own, and scratch in the later
  // slots of its region (which this sink fills after it, in order).
  [[gnu::always_inline]] std::uint32_t plane_room(const TriangleSlot& slot) const {
    if (slot.entry_index & kOverflowBit) return varyings_;
    return chunk_.planes_begin + chunk_.triangles.capacity * varyings_ - slot.plane_index;
  }
  [[gnu::always_inline]] void add_reserved_triangle(const TriangleSlot& slot) {
    const SetupTriangle& t = *slot.triangle;
    append(slot.entry_index, &t, t.min_x, t.min_y, t.max_x, t.max_y);
  }

  // A place for the next line, whose pixel bounding box is given.
  SetupLine& add_line(int min_x, int min_y, int max_x, int max_y) {
    GeometryChunk::Region& r = chunk_.lines;
    if (r.used < r.capacity) {
      const std::uint32_t index = r.begin + r.used++;
      append(index | kLineBit, nullptr, min_x, min_y, max_x, max_y);
      return lines_[index];
    }
    PrimitiveBuffer& o = chunk_.overflow;
    append(static_cast<std::uint32_t>(o.lines.size()) | kOverflowBit | kLineBit, nullptr, min_x,
           min_y, max_x, max_y);
    return o.lines.emplace_back();
  }

  // A place for the next point, whose pixel box is given. Its region has room for every point
  // of the chunk (a point is never split), so there is no overflow.
  SetupPoint& add_point(int min_x, int min_y, int max_x, int max_y) {
    GeometryChunk::Region& r = chunk_.points;
    assert(r.used < r.capacity);
    const std::uint32_t index = r.begin + r.used++;
    append(index | kPointBit, nullptr, min_x, min_y, max_x, max_y);
    return points_[index];
  }

 private:
  void append(std::uint32_t index, const SetupTriangle* triangle, int min_x, int min_y, int max_x,
              int max_y) {
    const SequenceEntry entry = binning_entry(frame_, index, triangle, min_x, min_y, max_x, max_y);
    GeometryChunk::Region& r = chunk_.entries;
    if (r.used < r.capacity) {
      sequence_[r.begin + r.used++] = entry;
    } else {
      chunk_.more_entries.push_back(entry);
    }
  }

  const Frame& frame_;

  SetupTriangle* triangles_;
  Plane* planes_;
  SetupLine* lines_;
  SetupPoint* points_;
  SequenceEntry* sequence_;
  GeometryChunk& chunk_;
  std::uint32_t varyings_;
};

}  // namespace facet::pipeline
