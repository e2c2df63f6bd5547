// The Utah teapot: Newell's 32 bicubic Bézier patches tessellated into one smooth indexed mesh.
// Written here when a scene asks for it; read by the vertex stage like any loaded mesh.
//
// Conventions (checked by tests/teapot_test.cpp):
//  * Newell's data is Z up; facet is Y up. (x, y, z) -> (x, z, -y) is a quarter turn about +X —
//    a rotation, so outward stays outward — that keeps the spout on +X, puts the handle on -X
//    and stands the teapot on y = 0 with its body around the Y axis. The classic units stay:
//    height 3.15, body radius 2, handle back at x = -3, spout tip near x = 3.43.
//  * front faces are counter-clockwise seen from outside, as in procedural.hpp;
//  * texture space holds one unit square per patch, placed so that the coordinates run on
//    across seams (see kPlacement); tangents point along +u with w = +1.
#include "facet/teapot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "facet/error.hpp"

namespace facet {
namespace {

using glm::dvec3;
using glm::vec2;
using glm::vec3;

constexpr int kControlPointCount = 306;
constexpr int kPatchCount = 32;
constexpr int kMaxSubdivisions = 64;

// clang-format off

// The classic teapot data set (Martin Newell, 1975; public domain; its history is in Crow, "The
// Origins of the Teapot", IEEE CG&A, January 1987) as it is usually distributed: Z up, three
// points to a line, the comment numbering the line's first point from 1. Points 205, 206, 216
// and 223 belong to the set but no patch uses them.
constexpr double kControlPoints[kControlPointCount][3] = {
    {1.4, 0, 2.4}, {1.4, -0.784, 2.4}, {0.784, -1.4, 2.4},                          // 1
    {0, -1.4, 2.4}, {1.3375, 0, 2.53125}, {1.3375, -0.749, 2.53125},                // 4
    {0.749, -1.3375, 2.53125}, {0, -1.3375, 2.53125}, {1.4375, 0, 2.53125},         // 7
    {1.4375, -0.805, 2.53125}, {0.805, -1.4375, 2.53125}, {0, -1.4375, 2.53125},    // 10
    {1.5, 0, 2.4}, {1.5, -0.84, 2.4}, {0.84, -1.5, 2.4},                            // 13
    {0, -1.5, 2.4}, {-0.784, -1.4, 2.4}, {-1.4, -0.784, 2.4},                       // 16
    {-1.4, 0, 2.4}, {-0.749, -1.3375, 2.53125}, {-1.3375, -0.749, 2.53125},         // 19
    {-1.3375, 0, 2.53125}, {-0.805, -1.4375, 2.53125}, {-1.4375, -0.805, 2.53125},  // 22
    {-1.4375, 0, 2.53125}, {-0.84, -1.5, 2.4}, {-1.5, -0.84, 2.4},                  // 25
    {-1.5, 0, 2.4}, {-1.4, 0.784, 2.4}, {-0.784, 1.4, 2.4},                         // 28
    {0, 1.4, 2.4}, {-1.3375, 0.749, 2.53125}, {-0.749, 1.3375, 2.53125},            // 31
    {0, 1.3375, 2.53125}, {-1.4375, 0.805, 2.53125}, {-0.805, 1.4375, 2.53125},     // 34
    {0, 1.4375, 2.53125}, {-1.5, 0.84, 2.4}, {-0.84, 1.5, 2.4},                     // 37
    {0, 1.5, 2.4}, {0.784, 1.4, 2.4}, {1.4, 0.784, 2.4},                            // 40
    {0.749, 1.3375, 2.53125}, {1.3375, 0.749, 2.53125}, {0.805, 1.4375, 2.53125},   // 43
    {1.4375, 0.805, 2.53125}, {0.84, 1.5, 2.4}, {1.5, 0.84, 2.4},                   // 46
    {1.75, 0, 1.875}, {1.75, -0.98, 1.875}, {0.98, -1.75, 1.875},                   // 49
    {0, -1.75, 1.875}, {2, 0, 1.35}, {2, -1.12, 1.35},                              // 52
    {1.12, -2, 1.35}, {0, -2, 1.35}, {2, 0, 0.9},                                   // 55
    {2, -1.12, 0.9}, {1.12, -2, 0.9}, {0, -2, 0.9},                                 // 58
    {-0.98, -1.75, 1.875}, {-1.75, -0.98, 1.875}, {-1.75, 0, 1.875},                // 61
    {-1.12, -2, 1.35}, {-2, -1.12, 1.35}, {-2, 0, 1.35},                            // 64
    {-1.12, -2, 0.9}, {-2, -1.12, 0.9}, {-2, 0, 0.9},                               // 67
    {-1.75, 0.98, 1.875}, {-0.98, 1.75, 1.875}, {0, 1.75, 1.875},                   // 70
    {-2, 1.12, 1.35}, {-1.12, 2, 1.35}, {0, 2, 1.35},                               // 73
    {-2, 1.12, 0.9}, {-1.12, 2, 0.9}, {0, 2, 0.9},                                  // 76
    {0.98, 1.75, 1.875}, {1.75, 0.98, 1.875}, {1.12, 2, 1.35},                      // 79
    {2, 1.12, 1.35}, {1.12, 2, 0.9}, {2, 1.12, 0.9},                                // 82
    {2, 0, 0.45}, {2, -1.12, 0.45}, {1.12, -2, 0.45},                               // 85
    {0, -2, 0.45}, {1.5, 0, 0.225}, {1.5, -0.84, 0.225},                            // 88
    {0.84, -1.5, 0.225}, {0, -1.5, 0.225}, {1.5, 0, 0.15},                          // 91
    {1.5, -0.84, 0.15}, {0.84, -1.5, 0.15}, {0, -1.5, 0.15},                        // 94
    {-1.12, -2, 0.45}, {-2, -1.12, 0.45}, {-2, 0, 0.45},                            // 97
    {-0.84, -1.5, 0.225}, {-1.5, -0.84, 0.225}, {-1.5, 0, 0.225},                   // 100
    {-0.84, -1.5, 0.15}, {-1.5, -0.84, 0.15}, {-1.5, 0, 0.15},                      // 103
    {-2, 1.12, 0.45}, {-1.12, 2, 0.45}, {0, 2, 0.45},                               // 106
    {-1.5, 0.84, 0.225}, {-0.84, 1.5, 0.225}, {0, 1.5, 0.225},                      // 109
    {-1.5, 0.84, 0.15}, {-0.84, 1.5, 0.15}, {0, 1.5, 0.15},                         // 112
    {1.12, 2, 0.45}, {2, 1.12, 0.45}, {0.84, 1.5, 0.225},                           // 115
    {1.5, 0.84, 0.225}, {0.84, 1.5, 0.15}, {1.5, 0.84, 0.15},                       // 118
    {-1.6, 0, 2.025}, {-1.6, -0.3, 2.025}, {-1.5, -0.3, 2.25},                      // 121
    {-1.5, 0, 2.25}, {-2.3, 0, 2.025}, {-2.3, -0.3, 2.025},                         // 124
    {-2.5, -0.3, 2.25}, {-2.5, 0, 2.25}, {-2.7, 0, 2.025},                          // 127
    {-2.7, -0.3, 2.025}, {-3, -0.3, 2.25}, {-3, 0, 2.25},                           // 130
    {-2.7, 0, 1.8}, {-2.7, -0.3, 1.8}, {-3, -0.3, 1.8},                             // 133
    {-3, 0, 1.8}, {-1.5, 0.3, 2.25}, {-1.6, 0.3, 2.025},                            // 136
    {-2.5, 0.3, 2.25}, {-2.3, 0.3, 2.025}, {-3, 0.3, 2.25},                         // 139
    {-2.7, 0.3, 2.025}, {-3, 0.3, 1.8}, {-2.7, 0.3, 1.8},                           // 142
    {-2.7, 0, 1.575}, {-2.7, -0.3, 1.575}, {-3, -0.3, 1.35},                        // 145
    {-3, 0, 1.35}, {-2.5, 0, 1.125}, {-2.5, -0.3, 1.125},                           // 148
    {-2.65, -0.3, 0.9375}, {-2.65, 0, 0.9375}, {-2, -0.3, 0.9},                     // 151
    {-1.9, -0.3, 0.6}, {-1.9, 0, 0.6}, {-3, 0.3, 1.35},                             // 154
    {-2.7, 0.3, 1.575}, {-2.65, 0.3, 0.9375}, {-2.5, 0.3, 1.125},                   // 157
    {-1.9, 0.3, 0.6}, {-2, 0.3, 0.9}, {1.7, 0, 1.425},                              // 160
    {1.7, -0.66, 1.425}, {1.7, -0.66, 0.6}, {1.7, 0, 0.6},                          // 163
    {2.6, 0, 1.425}, {2.6, -0.66, 1.425}, {3.1, -0.66, 0.825},                      // 166
    {3.1, 0, 0.825}, {2.3, 0, 2.1}, {2.3, -0.25, 2.1},                              // 169
    {2.4, -0.25, 2.025}, {2.4, 0, 2.025}, {2.7, 0, 2.4},                            // 172
    {2.7, -0.25, 2.4}, {3.3, -0.25, 2.4}, {3.3, 0, 2.4},                            // 175
    {1.7, 0.66, 0.6}, {1.7, 0.66, 1.425}, {3.1, 0.66, 0.825},                       // 178
    {2.6, 0.66, 1.425}, {2.4, 0.25, 2.025}, {2.3, 0.25, 2.1},                       // 181
    {3.3, 0.25, 2.4}, {2.7, 0.25, 2.4}, {2.8, 0, 2.475},                            // 184
    {2.8, -0.25, 2.475}, {3.525, -0.25, 2.49375}, {3.525, 0, 2.49375},              // 187
    {2.9, 0, 2.475}, {2.9, -0.15, 2.475}, {3.45, -0.15, 2.5125},                    // 190
    {3.45, 0, 2.5125}, {2.8, 0, 2.4}, {2.8, -0.15, 2.4},                            // 193
    {3.2, -0.15, 2.4}, {3.2, 0, 2.4}, {3.525, 0.25, 2.49375},                       // 196
    {2.8, 0.25, 2.475}, {3.45, 0.15, 2.5125}, {2.9, 0.15, 2.475},                   // 199
    {3.2, 0.15, 2.4}, {2.8, 0.15, 2.4}, {0, 0, 3.15},                               // 202
    {0, -0.002, 3.15}, {0.002, 0, 3.15}, {0.8, 0, 3.15},                            // 205
    {0.8, -0.45, 3.15}, {0.45, -0.8, 3.15}, {0, -0.8, 3.15},                        // 208
    {0, 0, 2.85}, {0.2, 0, 2.7}, {0.2, -0.112, 2.7},                                // 211
    {0.112, -0.2, 2.7}, {0, -0.2, 2.7}, {-0.002, 0, 3.15},                          // 214
    {-0.45, -0.8, 3.15}, {-0.8, -0.45, 3.15}, {-0.8, 0, 3.15},                      // 217
    {-0.112, -0.2, 2.7}, {-0.2, -0.112, 2.7}, {-0.2, 0, 2.7},                       // 220
    {0, 0.002, 3.15}, {-0.8, 0.45, 3.15}, {-0.45, 0.8, 3.15},                       // 223
    {0, 0.8, 3.15}, {-0.2, 0.112, 2.7}, {-0.112, 0.2, 2.7},                         // 226
    {0, 0.2, 2.7}, {0.45, 0.8, 3.15}, {0.8, 0.45, 3.15},                            // 229
    {0.112, 0.2, 2.7}, {0.2, 0.112, 2.7}, {0.4, 0, 2.55},                           // 232
    {0.4, -0.224, 2.55}, {0.224, -0.4, 2.55}, {0, -0.4, 2.55},                      // 235
    {1.3, 0, 2.55}, {1.3, -0.728, 2.55}, {0.728, -1.3, 2.55},                       // 238
    {0, -1.3, 2.55}, {1.3, 0, 2.4}, {1.3, -0.728, 2.4},                             // 241
    {0.728, -1.3, 2.4}, {0, -1.3, 2.4}, {-0.224, -0.4, 2.55},                       // 244
    {-0.4, -0.224, 2.55}, {-0.4, 0, 2.55}, {-0.728, -1.3, 2.55},                    // 247
    {-1.3, -0.728, 2.55}, {-1.3, 0, 2.55}, {-0.728, -1.3, 2.4},                     // 250
    {-1.3, -0.728, 2.4}, {-1.3, 0, 2.4}, {-0.4, 0.224, 2.55},                       // 253
    {-0.224, 0.4, 2.55}, {0, 0.4, 2.55}, {-1.3, 0.728, 2.55},                       // 256
    {-0.728, 1.3, 2.55}, {0, 1.3, 2.55}, {-1.3, 0.728, 2.4},                        // 259
    {-0.728, 1.3, 2.4}, {0, 1.3, 2.4}, {0.224, 0.4, 2.55},                          // 262
    {0.4, 0.224, 2.55}, {0.728, 1.3, 2.55}, {1.3, 0.728, 2.55},                     // 265
    {0.728, 1.3, 2.4}, {1.3, 0.728, 2.4}, {0, 0, 0},                                // 268
    {1.5, 0, 0.15}, {1.5, 0.84, 0.15}, {0.84, 1.5, 0.15},                           // 271
    {0, 1.5, 0.15}, {1.5, 0, 0.075}, {1.5, 0.84, 0.075},                            // 274
    {0.84, 1.5, 0.075}, {0, 1.5, 0.075}, {1.425, 0, 0},                             // 277
    {1.425, 0.798, 0}, {0.798, 1.425, 0}, {0, 1.425, 0},                            // 280
    {-0.84, 1.5, 0.15}, {-1.5, 0.84, 0.15}, {-1.5, 0, 0.15},                        // 283
    {-0.84, 1.5, 0.075}, {-1.5, 0.84, 0.075}, {-1.5, 0, 0.075},                     // 286
    {-0.798, 1.425, 0}, {-1.425, 0.798, 0}, {-1.425, 0, 0},                         // 289
    {-1.5, -0.84, 0.15}, {-0.84, -1.5, 0.15}, {0, -1.5, 0.15},                      // 292
    {-1.5, -0.84, 0.075}, {-0.84, -1.5, 0.075}, {0, -1.5, 0.075},                   // 295
    {-1.425, -0.798, 0}, {-0.798, -1.425, 0}, {0, -1.425, 0},                       // 298
    {0.84, -1.5, 0.15}, {1.5, -0.84, 0.15}, {0.84, -1.5, 0.075},                    // 301
    {1.5, -0.84, 0.075}, {0.798, -1.425, 0}, {1.425, -0.798, 0},                    // 304
};

// The 32 patches as 4 x 4 control points, row by row, numbered from 1 as in the published
// table. A patch's parameters are s, down the rows, and t, along them; cross(dP/dt, dP/ds)
// points out of the teapot on every patch.
constexpr std::uint16_t kPatches[kPatchCount][16] = {
    // rim
    {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16},
    {4, 17, 18, 19, 8, 20, 21, 22, 12, 23, 24, 25, 16, 26, 27, 28},
    {19, 29, 30, 31, 22, 32, 33, 34, 25, 35, 36, 37, 28, 38, 39, 40},
    {31, 41, 42, 1, 34, 43, 44, 5, 37, 45, 46, 9, 40, 47, 48, 13},
    // body, upper
    {13, 14, 15, 16, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60},
    {16, 26, 27, 28, 52, 61, 62, 63, 56, 64, 65, 66, 60, 67, 68, 69},
    {28, 38, 39, 40, 63, 70, 71, 72, 66, 73, 74, 75, 69, 76, 77, 78},
    {40, 47, 48, 13, 72, 79, 80, 49, 75, 81, 82, 53, 78, 83, 84, 57},
    // body, lower
    {57, 58, 59, 60, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96},
    {60, 67, 68, 69, 88, 97, 98, 99, 92, 100, 101, 102, 96, 103, 104, 105},
    {69, 76, 77, 78, 99, 106, 107, 108, 102, 109, 110, 111, 105, 112, 113, 114},
    {78, 83, 84, 57, 108, 115, 116, 85, 111, 117, 118, 89, 114, 119, 120, 93},
    // handle
    {121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136},
    {124, 137, 138, 121, 128, 139, 140, 125, 132, 141, 142, 129, 136, 143, 144, 133},
    {133, 134, 135, 136, 145, 146, 147, 148, 149, 150, 151, 152, 69, 153, 154, 155},
    {136, 143, 144, 133, 148, 156, 157, 145, 152, 158, 159, 149, 155, 160, 161, 69},
    // spout
    {162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177},
    {165, 178, 179, 162, 169, 180, 181, 166, 173, 182, 183, 170, 177, 184, 185, 174},
    {174, 175, 176, 177, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197},
    {177, 184, 185, 174, 189, 198, 199, 186, 193, 200, 201, 190, 197, 202, 203, 194},
    // lid, knob
    {204, 204, 204, 204, 207, 208, 209, 210, 211, 211, 211, 211, 212, 213, 214, 215},
    {204, 204, 204, 204, 210, 217, 218, 219, 211, 211, 211, 211, 215, 220, 221, 222},
    {204, 204, 204, 204, 219, 224, 225, 226, 211, 211, 211, 211, 222, 227, 228, 229},
    {204, 204, 204, 204, 226, 230, 231, 207, 211, 211, 211, 211, 229, 232, 233, 212},
    // lid
    {212, 213, 214, 215, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245},
    {215, 220, 221, 222, 237, 246, 247, 248, 241, 249, 250, 251, 245, 252, 253, 254},
    {222, 227, 228, 229, 248, 255, 256, 257, 251, 258, 259, 260, 254, 261, 262, 263},
    {229, 232, 233, 212, 257, 264, 265, 234, 260, 266, 267, 238, 263, 268, 269, 242},
    // bottom
    {270, 270, 270, 270, 279, 280, 281, 282, 275, 276, 277, 278, 271, 272, 273, 274},
    {270, 270, 270, 270, 282, 289, 290, 291, 278, 286, 287, 288, 274, 283, 284, 285},
    {270, 270, 270, 270, 291, 298, 299, 300, 288, 295, 296, 297, 285, 292, 293, 294},
    {270, 270, 270, 270, 300, 305, 306, 279, 297, 303, 304, 275, 294, 301, 302, 271},
};

// Where each patch lies in texture space: texcoord = corner + (t, s), or corner + (1 - t, 1 - s)
// with half_turn. Either way (u, v) turns like (t, s), so no patch is mirrored, the front stays
// counter-clockwise in texture space too, and the tangent handedness is +1. The corners make the
// coordinates continuous across seams: around the body, lid and bottom u counts quarter turns
// counter-clockwise from +X seen from above (u = 0 and u = 4 meet at +X); v climbs bottom centre
// (0) -> lower body (1) -> upper body (2) -> rim (3) -> 4 at the inner edge of the rim, and lid
// edge (0) -> knob base (1) -> knob top (2). Around the spout and handle tubes u counts half
// turns, and v runs from the body outwards along them.
struct Placement {
  float u, v;
  bool half_turn;
};
constexpr Placement kPlacement[kPatchCount] = {
    {3, 3, true},  {2, 3, true},  {1, 3, true},  {0, 3, true},   // rim
    {3, 2, true},  {2, 2, true},  {1, 2, true},  {0, 2, true},   // body, upper
    {3, 1, true},  {2, 1, true},  {1, 1, true},  {0, 1, true},   // body, lower
    {0, 0, false}, {1, 0, false}, {0, 1, false}, {1, 1, false},  // handle
    {0, 0, false}, {1, 0, false}, {0, 1, false}, {1, 1, false},  // spout
    {3, 1, true},  {2, 1, true},  {1, 1, true},  {0, 1, true},   // lid, knob
    {3, 0, true},  {2, 0, true},  {1, 0, true},  {0, 0, true},   // lid
    {0, 0, false}, {1, 0, false}, {2, 0, false}, {3, 0, false},  // bottom
};

// clang-format on

// The table's invariants, checked once by the compiler: indices in range, and the only patch
// edges that collapse to a point are first rows (the knob top and the bottom centre). Those
// are the only places where tessellate() needs a fan and frame_at() a limit.
constexpr bool first_row_collapses(int patch) {
  const auto& p = kPatches[patch];
  return p[0] == p[1] && p[1] == p[2] && p[2] == p[3];
}
constexpr bool edge_collapses(int patch, int first, int step) {
  const auto& p = kPatches[patch];
  return p[first] == p[first + step] && p[first] == p[first + 2 * step] &&
         p[first] == p[first + 3 * step];
}
constexpr bool table_is_sound() {
  for (int patch = 0; patch < kPatchCount; ++patch) {
    for (const std::uint16_t index : kPatches[patch]) {
      if (index < 1 || index > kControlPointCount) return false;
    }
    // Last row, first column, last column.
    if (edge_collapses(patch, 12, 1) || edge_collapses(patch, 0, 4) ||
        edge_collapses(patch, 3, 4)) {
      return false;
    }
  }
  return true;
}
static_assert(table_is_sound());

// --- evaluating a patch ----------------------------------------------------------------------

struct Patch {
  dvec3 points[4][4];  // [row][column], Y up
};

Patch load_patch(int patch) {
  Patch out;
  for (int k = 0; k < 16; ++k) {
    const double* p = kControlPoints[kPatches[patch][k] - 1];
    out.points[k / 4][k % 4] = dvec3(p[0], p[2], -p[1]);  // Z up -> Y up, see the top
  }
  return out;
}

// The cubic Bernstein weights at x and their derivatives.
struct Bernstein {
  double weight[4];
  double slope[4];
};

Bernstein bernstein(double x) {
  const double y = 1.0 - x;
  return {{y * y * y, 3.0 * x * y * y, 3.0 * x * x * y, x * x * x},
          {-3.0 * y * y, 3.0 * y * y - 6.0 * x * y, 6.0 * x * y - 3.0 * x * x, 3.0 * x * x}};
}

struct Sample {
  dvec3 position{0.0};
  dvec3 d_ds{0.0};  // dP/ds, down the rows
  dvec3 d_dt{0.0};  // dP/dt, along them
};

Sample evaluate(const Patch& patch, double s, double t) {
  const Bernstein bs = bernstein(s), bt = bernstein(t);
  Sample out;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      const dvec3& p = patch.points[r][c];
      out.position += bs.weight[r] * bt.weight[c] * p;
      out.d_ds += bs.slope[r] * bt.weight[c] * p;
      out.d_dt += bs.weight[r] * bt.slope[c] * p;
    }
  }
  return out;
}

// The derivatives are unusable when they are (nearly) parallel or one of them (nearly) vanishes:
// |a x b| <= k (|a|^2 + |b|^2) catches both, since |a|^2 + |b|^2 >= 2 |a| |b|.
constexpr double kDegenerate = 1e-9;
// How far inside the patch the frame of a degenerate sample is taken; the frame is smooth, so
// this is its limit to within about this many radians.
constexpr double kInset = 1e-5;

struct Frame {
  vec3 normal;   // unit, outward
  vec3 tangent;  // unit, along +u, perpendicular to the normal
};

// The outward normal cross(dP/dt, dP/ds) and the tangent along +u (+-dP/dt). Along a collapsed
// first row dP/dt is zero, so both vanish there although the surface is smooth (the knob top and
// the bottom centre are flat, facing straight up and down): the frame is then taken a hair
// inside the patch, the neighbouring sample of the limit.
Frame frame_at(const Patch& patch, Sample x, double s, double t, bool half_turn) {
  auto degenerate = [](const Sample& y) {
    return glm::length(glm::cross(y.d_dt, y.d_ds)) <=
           kDegenerate * (glm::dot(y.d_dt, y.d_dt) + glm::dot(y.d_ds, y.d_ds));
  };
  if (degenerate(x)) {
    auto inset = [](double p) { return p < 0.5 ? p + kInset : p - kInset; };
    x = evaluate(patch, inset(s), inset(t));
  }
  const dvec3 normal = glm::normalize(glm::cross(x.d_dt, x.d_ds));
  const dvec3 along_u = half_turn ? -x.d_dt : x.d_dt;
  const dvec3 tangent = glm::normalize(along_u - normal * glm::dot(normal, along_u));
  return {vec3(normal), vec3(tangent)};
}

// --- tessellating ----------------------------------------------------------------------------

// Every patch on its own, before welding: (n + 1)^2 samples and 2 n^2 triangles, or 2 n^2 - n
// where the first row collapses.
struct Patches {
  std::vector<vec3> positions, normals, tangents;
  std::vector<vec2> texcoords;
  std::vector<std::uint32_t> indices;
};

void tessellate(int patch_index, int n, Patches& out) {
  const Patch patch = load_patch(patch_index);
  const Placement place = kPlacement[patch_index];
  const bool fan = first_row_collapses(patch_index);
  const auto first = static_cast<std::uint32_t>(out.positions.size());
  const auto row = static_cast<std::uint32_t>(n) + 1;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      // A collapsed first row is one point; each of its samples is the tip of one fan triangle
      // and is taken mid-segment, where that triangle's texture wants it (the last is unused).
      const double s = static_cast<double>(i) / n;
      const double t = (fan && i == 0 ? std::min(j + 0.5, static_cast<double>(n)) : j) / n;
      const Sample x = evaluate(patch, s, t);
      const Frame frame = frame_at(patch, x, s, t, place.half_turn);
      const double u = place.half_turn ? 1.0 - t : t, v = place.half_turn ? 1.0 - s : s;
      out.positions.push_back(vec3(x.position));
      out.normals.push_back(frame.normal);
      out.tangents.push_back(frame.tangent);
      out.texcoords.push_back(vec2(place.u + u, place.v + v));
    }
  }
  for (std::uint32_t i = 0; i < row - 1; ++i) {
    for (std::uint32_t j = 0; j < row - 1; ++j) {
      // Counter-clockwise in (t, s), which is counter-clockwise seen from outside.
      const std::uint32_t a = first + i * row + j, b = a + 1, c = a + row + 1, d = a + row;
      if (!(fan && i == 0)) out.indices.insert(out.indices.end(), {a, b, c});  // a == b there
      out.indices.insert(out.indices.end(), {a, c, d});
    }
  }
}

// --- welding ---------------------------------------------------------------------------------

// Samples closer than this are one point. Neighbouring patches evaluate their shared edge from
// the same control points in double precision, so they agree to a float ulp or two.
constexpr float kWeldDistance = 1e-6f;
// Normals within this angle are one direction. The seams between neighbouring patches are
// smooth (their normals agree to 0.03 degrees, the data being rounded to 3 decimals), while the
// ends of the handle and the spout meet the body at over 100 degrees and stay apart.
constexpr float kWeldDegrees = 3.0f;
// Texture coordinates closer than this are equal; the samples of one patch are >= 1/64 apart.
constexpr float kWeldTexcoord = 1e-5f;
// Spatial hash cells at least kWeldDistance wide, so a match lies in the 27 cells around a
// point. The teapot spans |coordinate| < 4, i.e. < 4e5 cells: inside the 21 bits per axis.
constexpr float kCellSize = 1e-5f;

std::uint64_t cell_key(glm::ivec3 cell) {
  constexpr int kBias = 1 << 20;
  auto bits = [](int c) { return static_cast<std::uint64_t>(c + kBias) & 0x1fffff; };
  return bits(cell.x) << 42 | bits(cell.y) << 21 | bits(cell.z);
}

// Merges the patches' samples in two steps. Samples at one point with one normal direction form
// a smooth group, which gets one normal (their mean), so both sides of a seam shade alike.
// Within a group, samples with the same texture coordinates become one vertex; where the
// coordinates jump (u = 0 against u = 4 at +X, the fan tips at the poles) a group keeps several
// vertices, all with the group's position and normal, so the surface stays closed and smooth.
class Welder {
 public:
  explicit Welder(const Patches& in) : in_(in), vertex_of_(in.positions.size(), kNone) {}

  Mesh run() {
    // Vertices are numbered in the order the triangles first use them; unused samples vanish.
    mesh_.indices.reserve(in_.indices.size());
    for (const std::uint32_t sample : in_.indices) mesh_.indices.push_back(vertex(sample));
    for (std::size_t v = 0; v < mesh_.positions.size(); ++v) {
      const vec3 normal = glm::normalize(groups_[group_of_vertex_[v]].normal_sum);
      const vec3 t = tangent_sum_[v];
      mesh_.normals.push_back(normal);
      mesh_.tangents.push_back(glm::vec4(glm::normalize(t - normal * glm::dot(normal, t)), 1.0f));
    }
    return std::move(mesh_);
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  struct Group {
    vec3 position;
    vec3 normal;  // of the first sample, to compare others with
    vec3 normal_sum{0.0f};
    std::vector<std::uint32_t> vertices;
  };

  std::uint32_t vertex(std::uint32_t sample) {
    if (vertex_of_[sample] != kNone) return vertex_of_[sample];
    const std::uint32_t g = group_of(sample);
    groups_[g].normal_sum += in_.normals[sample];
    const vec2 uv = in_.texcoords[sample];
    for (const std::uint32_t v : groups_[g].vertices) {
      const vec2 d = glm::abs(mesh_.texcoords[v] - uv);
      if (std::max(d.x, d.y) <= kWeldTexcoord) {
        tangent_sum_[v] += in_.tangents[sample];
        return vertex_of_[sample] = v;
      }
    }
    const auto v = static_cast<std::uint32_t>(mesh_.positions.size());
    mesh_.positions.push_back(groups_[g].position);
    mesh_.texcoords.push_back(uv);
    tangent_sum_.push_back(in_.tangents[sample]);
    group_of_vertex_.push_back(g);
    groups_[g].vertices.push_back(v);
    return vertex_of_[sample] = v;
  }

  std::uint32_t group_of(std::uint32_t sample) {
    static const float kMinCosine = std::cos(glm::radians(kWeldDegrees));
    const vec3 p = in_.positions[sample], n = in_.normals[sample];
    const glm::ivec3 cell(glm::floor(p / kCellSize));
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find(cell_key(cell + glm::ivec3(dx, dy, dz)));
          if (found == cells_.end()) continue;
          for (const std::uint32_t g : found->second) {
            if (glm::distance(groups_[g].position, p) <= kWeldDistance &&
                glm::dot(groups_[g].normal, n) >= kMinCosine) {
              return g;
            }
          }
        }
      }
    }
    const auto g = static_cast<std::uint32_t>(groups_.size());
    groups_.push_back({p, n, vec3(0.0f), {}});
    cells_[cell_key(cell)].push_back(g);
    return g;
  }

  const Patches& in_;
  std::vector<std::uint32_t> vertex_of_;  // per sample
  std::vector<Group> groups_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;  // cell -> groups
  std::vector<std::uint32_t> group_of_vertex_;
  std::vector<vec3> tangent_sum_;  // per vertex
  Mesh mesh_;
};

}  // namespace

Mesh teapot(int subdivisions) {
  // 64 already gives 262 thousand triangles, smaller than a pixel at any sensible view.
  if (subdivisions < 1 || subdivisions > kMaxSubdivisions) {
    throw Error("teapot: subdivisions is " + std::to_string(subdivisions) +
                " but must be between 1 and " + std::to_string(kMaxSubdivisions));
  }
  const auto samples =
      static_cast<std::size_t>(kPatchCount * (subdivisions + 1) * (subdivisions + 1));
  Patches patches;
  patches.positions.reserve(samples);
  patches.normals.reserve(samples);
  patches.tangents.reserve(samples);
  patches.texcoords.reserve(samples);
  for (int p = 0; p < kPatchCount; ++p) tessellate(p, subdivisions, patches);
  return Welder(patches).run();
}

}  // namespace facet
