// PLY's body (header: ply_header.cpp, format: ply_format.hpp) to one mesh: the vertex element's
// positions, normals, texture coordinates and colors; the face element's polygons fanned into
// triangles (or tristrips' strips unrolled); every other element and property skipped. Written
// here at load time; the mesh is read by the renderer like any other. (Reading a file of it is
// ply_import.cpp: this file parses bytes alone, so its fuzz target links it alone.)
//
// Every read is checked against the end of the bytes, every index against the vertex count and
// every list length against what is left, so damaged or hostile bytes give one facet::Error
// "<name>: <what> (line N)" (ASCII) or "(byte N)" (binary), never a crash or a long loop.
#include "import/ply_format.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "facet/color.hpp"
#include "facet/error.hpp"
#include "facet/mesh_tools.hpp"
#include "import/import_internal.hpp"
#include "import/ply_values.hpp"

namespace facet::io {
namespace {

using ply::AsciiSource;
using ply::BinarySource;
using ply::Element;
using ply::list_length;
using ply::number;
using ply::Place;
using ply::Property;
using ply::Type;

// What a vertex property sets. The names are those writers use: Blender (s t), MeshLab
// (red green blue alpha, texture_u texture_v), scanners and old Stanford files (diffuse_red ...).
enum Slot : std::uint8_t { kNone, kX, kY, kZ, kNx, kNy, kNz, kU, kV, kRed, kGreen, kBlue, kAlpha };
constexpr int kSlots = 13;

Slot slot_of(std::string_view name) {
  struct Named {
    std::string_view name;
    Slot slot;
  };
  static constexpr Named kNames[] = {
      {"x", kX},
      {"y", kY},
      {"z", kZ},
      {"nx", kNx},
      {"ny", kNy},
      {"nz", kNz},
      {"normal_x", kNx},
      {"normal_y", kNy},
      {"normal_z", kNz},
      {"s", kU},
      {"t", kV},
      {"u", kU},
      {"v", kV},
      {"texture_u", kU},
      {"texture_v", kV},
      {"texture_s", kU},
      {"texture_t", kV},
      {"red", kRed},
      {"green", kGreen},
      {"blue", kBlue},
      {"alpha", kAlpha},
      {"r", kRed},
      {"g", kGreen},
      {"b", kBlue},
      {"a", kAlpha},
      {"diffuse_red", kRed},
      {"diffuse_green", kGreen},
      {"diffuse_blue", kBlue},
      {"diffuse_alpha", kAlpha},
  };
  for (const Named& known : kNames) {
    if (known.name == name) return known.slot;
  }
  return kNone;
}

bool is_color(Slot slot) { return slot >= kRed; }

// An integer color component's full scale (a byte's 255 is 1); floats are taken as they are.
double color_scale(Type type) {
  switch (type) {
    case Type::int8:
      return 127.0;
    case Type::uint8:
      return 255.0;
    case Type::int16:
      return 32767.0;
    case Type::uint16:
      return 65535.0;
    case Type::int32:
      return 2147483647.0;
    case Type::uint32:
      return 4294967295.0;
    case Type::float32:
    case Type::float64:
      break;
  }
  return 1.0;
}

// The body's items into the mesh, element by element in header order.
template <class Source>
class BodyReader {
 public:
  BodyReader(Source& source, Place& place, const ply::Header& header, std::size_t body_size,
             const std::string& name)
      : source_(source), place_(place), header_(header), body_size_(body_size), name_(name) {}

  // Positions (attributes alongside) and triangle indices; faces: whether any face or strip
  // element has items (else the file is a point cloud). Texture coordinates given per face
  // corner (MeshLab's `texcoord` list) come back one per index in corner_uvs (else empty).
  void read(Mesh& mesh, bool& faces, std::vector<glm::vec2>& corner_uvs) {
    faces = false;
    vertex_count_ = 0;
    for (const Element& element : header_.elements) {
      if (element.name == "vertex") {
        vertex_count_ = element.count;
        break;
      }
    }
    bool have_vertices = false;
    for (const Element& element : header_.elements) {
      place_ = Place{element.name, 0, element.count};
      if (element.name == "vertex" && !have_vertices) {
        read_vertices(element, mesh);
        have_vertices = true;
      } else if ((element.name == "face" || element.name == "tristrips") && element.count > 0) {
        read_faces(element, mesh);
        faces = true;
      } else if (!element.properties.empty()) {
        source_.skip_items(element.count, element);
      }
    }
    if (!corner_uvs_.empty()) corner_uvs_.resize(mesh.indices.size());  // strips after faces
    corner_uvs = std::move(corner_uvs_);
  }

 private:
  void read_vertices(const Element& element, Mesh& mesh) {
    if (element.count > std::numeric_limits<std::uint32_t>::max()) {
      fail(element, "more vertices than facet can index (" + std::to_string(element.count) + ")");
    }
    const std::size_t n = static_cast<std::size_t>(element.count);
    std::vector<Slot> slots;
    bool present[kSlots] = {};
    for (const Property& property : element.properties) {
      const Slot slot = property.is_list ? kNone : slot_of(property.name);
      slots.push_back(slot);
      present[slot] = true;
    }
    if (n > 0 && (!present[kX] || !present[kY] || !present[kZ])) {
      fail(element, "the vertex element has no x, y and z properties");
    }
    mesh.positions.resize(n);
    const bool normals = present[kNx] || present[kNy] || present[kNz];
    const bool texcoords = present[kU] || present[kV];
    const bool colors = present[kRed] || present[kGreen] || present[kBlue] || present[kAlpha];
    if (normals) mesh.normals.resize(n);
    if (texcoords) mesh.texcoords.resize(n);
    if (colors) mesh.colors.resize(n);
    float values[kSlots];
    for (std::size_t i = 0; i < n; ++i) {
      place_.index = i;
      std::fill(values, values + kSlots, 0.0f);
      values[kAlpha] = 1.0f;  // opaque unless the file says otherwise
      source_.begin_item();
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        if (property.is_list) {
          source_.skip_values(list_length(source_, property), property.type);
          continue;
        }
        const double value = source_.value(property.type);
        const Slot slot = slots[p];
        if (slot == kNone) continue;
        values[slot] =
            static_cast<float>(is_color(slot) ? value / color_scale(property.type) : value);
      }
      source_.end_item();
      mesh.positions[i] = {values[kX], values[kY], values[kZ]};
      if (normals) mesh.normals[i] = {values[kNx], values[kNy], values[kNz]};
      if (texcoords) mesh.texcoords[i] = {values[kU], values[kV]};
      if (colors) mesh.colors[i] = {values[kRed], values[kGreen], values[kBlue], values[kAlpha]};
    }
  }

  // One face's polygon, fanned (n - 2 triangles from its first corner), or one strip, unrolled
  // with every other triangle turned round and -1 restarting it (the tristrips convention).
  // A face's `texcoord` list (u v for each corner) gives its corners their own texture
  // coordinates; a face without a whole list gets (0, 0).
  void read_faces(const Element& element, Mesh& mesh) {
    const bool strips = element.name == "tristrips";
    const std::size_t none = element.properties.size();
    std::size_t list = none, uv_list = none;
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const Property& property = element.properties[p];
      if (property.is_list &&
          (property.name == "vertex_indices" || property.name == "vertex_index")) {
        list = p;
      }
      if (property.is_list && property.name == "texcoord" && !strips) uv_list = p;
    }
    if (list == none) {
      fail(element, "the " + element.name + " element has no vertex_indices list");
    }
    if (uv_list != none) corner_uvs_.resize(mesh.indices.size());  // earlier faces: (0, 0)
    // At least a byte per index in the file: no honest file needs more room than that.
    mesh.indices.reserve(std::min<std::uint64_t>(element.count * 3, body_size_));
    for (std::uint64_t i = 0; i < element.count; ++i) {
      place_.index = i;
      source_.begin_item();
      uvs_.clear();
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        if (!property.is_list) {
          source_.value(property.type);
        } else if (p == list) {
          read_corners(list_length(source_, property), property.type, strips);
        } else if (p == uv_list) {
          const std::uint64_t count = list_length(source_, property);
          for (std::uint64_t k = 0; k < count; ++k) {
            uvs_.push_back(static_cast<float>(source_.value(property.type)));
          }
        } else {
          source_.skip_values(list_length(source_, property), property.type);
        }
      }
      source_.end_item();
      if (strips) {
        append_strip(mesh);
      } else {
        append_fan(mesh, uv_list != none);
      }
    }
  }

  void read_corners(std::uint64_t count, Type type, bool strips) {
    corners_.clear();
    for (std::uint64_t k = 0; k < count; ++k) {
      const double index = source_.value(type);
      if (strips && index == -1.0) {
        corners_.push_back(kRestart);
        continue;
      }
      if (!(index >= 0.0) || index >= static_cast<double>(vertex_count_) ||
          index != std::floor(index)) {
        source_.fail(place_.item() + ": vertex index " + number(index) +
                     (vertex_count_ == 0
                          ? std::string(", but there are no vertices")
                          : " is out of range (0.." + std::to_string(vertex_count_ - 1) + ")"));
      }
      corners_.push_back(static_cast<std::uint32_t>(index));
    }
  }

  void append_fan(Mesh& mesh, bool with_uvs) {
    const bool whole = uvs_.size() == 2 * corners_.size();
    auto uv = [&](std::size_t k) {
      return whole ? glm::vec2(uvs_[2 * k], uvs_[2 * k + 1]) : glm::vec2(0.0f);
    };
    for (std::size_t k = 1; k + 1 < corners_.size(); ++k) {
      mesh.indices.insert(mesh.indices.end(), {corners_[0], corners_[k], corners_[k + 1]});
      if (with_uvs) corner_uvs_.insert(corner_uvs_.end(), {uv(0), uv(k), uv(k + 1)});
    }
  }

  void append_strip(Mesh& mesh) {
    std::size_t run = 0;  // corners since the strip (re)started
    for (std::size_t k = 0; k < corners_.size(); ++k) {
      if (corners_[k] == kRestart) {
        run = 0;
        continue;
      }
      if (++run < 3) continue;
      const std::uint32_t a = corners_[k - 2], b = corners_[k - 1], c = corners_[k];
      if (run % 2 == 1) {
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
      } else {
        mesh.indices.insert(mesh.indices.end(), {b, a, c});
      }
    }
  }

  // What the header says of an element that cannot be read: its declaration's line.
  [[noreturn]] void fail(const Element& element, const std::string& what) const {
    throw Error(name_ + ": " + what + " (line " + std::to_string(element.line) + ")");
  }

  static constexpr std::uint32_t kRestart = std::numeric_limits<std::uint32_t>::max();

  Source& source_;
  Place& place_;
  const ply::Header& header_;
  std::size_t body_size_;
  const std::string& name_;
  std::uint64_t vertex_count_ = 0;
  std::vector<std::uint32_t> corners_;
  std::vector<float> uvs_;             // the current face's texcoord list
  std::vector<glm::vec2> corner_uvs_;  // one per index once a face has a texcoord list
};

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Keeps the vertices `keep` says, in order, with their attributes; returns the new index of each
// old vertex (unused for those dropped).
std::vector<std::uint32_t> keep_vertices(Mesh& mesh, const std::vector<bool>& keep) {
  std::vector<std::uint32_t> remap(mesh.positions.size(), 0);
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    if (keep[i]) remap[i] = next++;
  }
  auto compact = [&](auto& attribute) {
    if (attribute.empty()) return;
    std::size_t out = 0;
    for (std::size_t i = 0; i < keep.size(); ++i) {
      if (keep[i]) attribute[out++] = attribute[i];
    }
    attribute.resize(out);
  };
  compact(mesh.positions), compact(mesh.normals), compact(mesh.texcoords), compact(mesh.colors);
  return remap;
}

// Points: those with a non-finite position are left out (scanners write NaN for a missing
// sample). Triangles: vertices no triangle uses are left out, as a reader that copies each
// corner would; a used vertex whose position is not finite is made NaN, which the pipeline
// skips the triangles of and bounds ignore. Returns how many positions were not finite.
std::size_t settle_positions(Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  std::size_t non_finite = 0;
  if (mesh.topology == Topology::points) {
    std::vector<bool> keep(n);
    for (std::size_t i = 0; i < n; ++i) {
      keep[i] = finite(mesh.positions[i]);
      non_finite += !keep[i];
    }
    if (non_finite > 0) keep_vertices(mesh, keep);
    return non_finite;
  }
  std::vector<bool> used(n, false);
  for (std::uint32_t index : mesh.indices) used[index] = true;
  if (std::find(used.begin(), used.end(), false) != used.end()) {
    const std::vector<std::uint32_t> remap = keep_vertices(mesh, used);
    for (std::uint32_t& index : mesh.indices) index = remap[index];
  }
  for (glm::vec3& p : mesh.positions) {
    if (finite(p)) continue;
    p = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    ++non_finite;
  }
  return non_finite;
}

// Attributes the pipeline could not shade sensibly: one broken normal spoils a smooth surface,
// so all are dropped (and computed again by the importer); a texture coordinate that is not
// finite becomes (0, 0), a color white. Colors are display (sRGB) values, as Blender and
// MeshLab read them: clamped to [0, 1] (an ASCII value beyond its type's range would otherwise
// decode to infinity), then made linear.
void settle_attributes(Mesh& mesh) {
  for (glm::vec3& normal : mesh.normals) {
    const float length = glm::length(normal);
    if (!(length > 1e-12f) || !std::isfinite(length)) {
      mesh.normals.clear();
      break;
    }
    normal /= length;
  }
  for (glm::vec2& uv : mesh.texcoords) {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
  }
  for (glm::vec4& color : mesh.colors) {
    if (!finite(glm::vec3(color)) || !std::isfinite(color.w)) {
      color = glm::vec4(1.0f);
      continue;
    }
    color = glm::clamp(color, glm::vec4(0.0f), glm::vec4(1.0f));
    color = glm::vec4(srgb_to_linear(glm::vec3(color)), color.w);
  }
}

// Texture coordinates per face corner: each corner becomes a vertex of its own, with the
// attributes of the vertex it names and its own texture coordinates (the importer joins those
// that are identical again), so a seam keeps both sides' coordinates.
void give_corners_their_uvs(Mesh& mesh, const std::vector<glm::vec2>& corner_uvs) {
  const std::size_t corners = mesh.indices.size();
  mesh.texcoords.clear();
  expand_indices(mesh);
  mesh.texcoords = corner_uvs;
  mesh.indices.resize(corners);
  for (std::size_t k = 0; k < corners; ++k) mesh.indices[k] = static_cast<std::uint32_t>(k);
}

template <class Source>
Mesh read_body(std::string_view bytes, const ply::Header& header, const std::string& name) {
  Place place;
  Source source(bytes, header, name, place);
  BodyReader<Source> reader(source, place, header, bytes.size() - header.body_offset, name);
  Mesh mesh;
  bool faces = false;
  std::vector<glm::vec2> corner_uvs;
  reader.read(mesh, faces, corner_uvs);
  mesh.topology = faces ? Topology::triangles : Topology::points;
  if (!corner_uvs.empty()) give_corners_their_uvs(mesh, corner_uvs);
  return mesh;
}

}  // namespace

PlyGeometry parse_ply_geometry(std::string_view bytes, const std::string& name) {
  const ply::Header header = ply::parse_header(bytes, name);
  const bool has_vertices = std::any_of(header.elements.begin(), header.elements.end(),
                                        [](const Element& e) { return e.name == "vertex"; });
  if (!has_vertices) {
    throw Error(name + ": the header declares no vertex element (line " +
                std::to_string(header.body_line - 1) + ")");
  }
  PlyGeometry out;
  switch (header.format) {
    case ply::Format::ascii:
      out.mesh = read_body<AsciiSource>(bytes, header, name);
      break;
    case ply::Format::binary_little_endian:
      out.mesh = read_body<BinarySource<std::endian::little>>(bytes, header, name);
      break;
    case ply::Format::binary_big_endian:
      out.mesh = read_body<BinarySource<std::endian::big>>(bytes, header, name);
      break;
  }
  out.non_finite = settle_positions(out.mesh);
  settle_attributes(out.mesh);
  out.texture_file = header.texture_file;
  return out;
}

}  // namespace facet::io
