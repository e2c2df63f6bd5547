// Classic rasterizer 2: scanlines with an edge table and an active edge table
// (docs/classic/scanline.md).
//
// The idea: walk the triangle a pixel row at a time. The edge table lists the edges by the
// first row they cross; the active edge table holds the edges crossing the current row, with
// their x there. Between each pair of active edges, sorted by x, lies a span of covered pixels.
// Going down a row adds dx/dy to each active edge's x: no test per pixel at all. Depth, 1/w and
// normal/w, affine on screen, are stepped down the edges too and interpolated along each span.
#include <algorithm>
#include <cmath>
#include <utility>

#include "classic/classic.hpp"

namespace facet::classic {
namespace {

// Stepped down an edge and along a span: window depth, 1/w, and the normal times 1/w.
constexpr int kValues = 5;

struct Edge {
  int first_row, last_row;  // the rows whose centre (y + 0.5) the edge crosses, in the image
  double x, dx;             // x where the edge crosses the current row's centre; per row
  double value[kValues], step[kValues];  // the values there; per row
};

void values_at(const ScreenVertex& v, double out[kValues]) {
  const double values[kValues] = {v.z, v.inv_w, v.normal.x * v.inv_w, v.normal.y * v.inv_w,
                                  v.normal.z * v.inv_w};
  std::copy_n(values, kValues, out);
}

// Insertion sort, enough for tables of at most three edges.
template <class T, class Less>
void sort_small(T* items, int count, Less less) {
  for (int i = 1; i < count; ++i) {
    for (int j = i; j > 0 && less(items[j], items[j - 1]); --j) std::swap(items[j], items[j - 1]);
  }
}

// The first pixel row (or column) whose centre is at or after `at`, within [0, size].
int centre_at_or_after(double at, int size) {
  return static_cast<int>(std::clamp(std::ceil(at - 0.5), 0.0, static_cast<double>(size)));
}

// The last pixel column whose centre is at or before `at`, within [-1, size - 1].
int centre_at_or_before(double at, int size) {
  return static_cast<int>(std::clamp(std::floor(at - 0.5), -1.0, size - 1.0));
}

// Fills row y between the active edges left and right: the pixels whose centre lies in
// [left.x, right.x), half open so that two triangles sharing an edge do not both take a centre
// on it (the right end is the neighbour's left end); closed without the rule.
void fill_span(const Edge& left, const Edge& right, int y, bool fill_rule, Image& image) {
  const int first = centre_at_or_after(left.x, image.width);
  const int last = fill_rule ? centre_at_or_after(right.x, image.width) - 1
                             : centre_at_or_before(right.x, image.width);
  const double width = right.x - left.x;
  for (int x = first; x <= last; ++x) {
    // Where the centre lies along the span, in [0, 1]: stable however narrow the span.
    const double f = width > 0.0 ? (x + 0.5 - left.x) / width : 0.0;
    double v[kValues];
    for (int k = 0; k < kValues; ++k) v[k] = left.value[k] + f * (right.value[k] - left.value[k]);
    // Perspective correction: normal / w divided by 1 / w.
    write_fragment(image, x, y, static_cast<float>(v[0]),
                   glm::vec3(glm::dvec3(v[2], v[3], v[4]) / v[1]));
  }
}

}  // namespace

void fill_scanline(const ScreenVertex v[3], bool fill_rule, Image& image) {
  // The edge table: each edge that crosses a row centre, its top end first, by first row. A
  // polygon of many edges keeps a list per row; a triangle's three edges, sorted, are that.
  Edge table[3];
  int edges = 0;
  for (int i = 0; i < 3; ++i) {
    const ScreenVertex* top = &v[i];
    const ScreenVertex* bottom = &v[(i + 1) % 3];
    if (top->y == bottom->y) continue;  // horizontal: its row is bounded by the other two
    if (top->y > bottom->y) std::swap(top, bottom);
    Edge& e = table[edges];
    // The rows whose centre lies in [top.y, bottom.y): half open, so a row through the corner
    // where two edges of one side meet is taken by one of them, and a row through a shared
    // horizontal edge by one of the two triangles.
    e.first_row = centre_at_or_after(top->y, image.height);
    e.last_row = centre_at_or_after(bottom->y, image.height) - 1;
    if (e.first_row > e.last_row) continue;
    const double height = double{bottom->y} - top->y;
    const double down = e.first_row + 0.5 - top->y;  // from the top end to the first row
    e.dx = (double{bottom->x} - top->x) / height;
    e.x = top->x + down * e.dx;
    double a[kValues], b[kValues];
    values_at(*top, a);
    values_at(*bottom, b);
    for (int k = 0; k < kValues; ++k) {
      e.step[k] = (b[k] - a[k]) / height;
      e.value[k] = a[k] + down * e.step[k];
    }
    ++edges;
  }
  sort_small(table, edges, [](const Edge& a, const Edge& b) { return a.first_row < b.first_row; });
  if (edges == 0) return;
  int last_row = 0;
  for (int i = 0; i < edges; ++i) last_row = std::max(last_row, table[i].last_row);

  // The walk: each row, move the edges starting there into the active edge table, drop those
  // that ended, sort by x, fill between pairs, then step every active edge down a row.
  Edge* active[3];
  int count = 0, next = 0;
  for (int y = table[0].first_row; y <= last_row; ++y) {
    while (next < edges && table[next].first_row <= y) active[count++] = &table[next++];
    count = static_cast<int>(
        std::remove_if(active, active + count, [y](const Edge* e) { return e->last_row < y; }) -
        active);
    sort_small(active, count, [](const Edge* a, const Edge* b) { return a->x < b->x; });
    for (int i = 0; i + 1 < count; i += 2)
      fill_span(*active[i], *active[i + 1], y, fill_rule, image);
    for (int i = 0; i < count; ++i) {
      Edge& e = *active[i];
      e.x += e.dx;
      for (int k = 0; k < kValues; ++k) e.value[k] += e.step[k];
    }
  }
}

}  // namespace facet::classic
