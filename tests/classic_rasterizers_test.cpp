// The classic rasterizers (src/classic, docs/classic/) against facet: coverage and depth
// against the reference rasterizer on random triangle soups, the shared-edge cracks and double
// hits each chapter describes, and the chapters' scenes against facet's own render. The
// pictures are goldens in docs/classic/, compared as tests/golden's are (a channel may differ by
// 2 levels, at most 0.1% of pixels by more); after an intended change regenerate them with
// FACET_UPDATE_GOLDENS=1 --gtest_filter='Classic*' and look at them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "classic/classic.hpp"
#include "facet/image_io.hpp"
#include "facet/import.hpp"
#include "facet/renderer.hpp"
#include "facet/worlds.hpp"
#include "pipeline/reference.hpp"
#include "support/geometry.hpp"
#include "support/golden.hpp"
#include "support/random_soup.hpp"
#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

using classic::Method;

constexpr Method kMethods[] = {Method::bounding_box, Method::scanline, Method::ray_per_pixel};
const char* const kMethodNames[] = {"bounding_box", "scanline", "ray_per_pixel"};

classic::Image draw(const Mesh& mesh, const Camera& camera, CullMode cull, Method method,
                    bool fill_rule, int width, int height) {
  classic::Image image(width, height);
  classic::draw_mesh(mesh, glm::mat4(1.0f), camera, cull, {method, fill_rule}, image);
  return image;
}

// --- Random soups against the reference rasterizer ----------------------------------------

constexpr int kWidth = 67;  // reference_test's size and camera
constexpr int kHeight = 43;
constexpr int kSoups = 300;

// How one rasterizer's soups differ from the reference's.
struct SoupDifference {
  long covered = 0;         // pixels the reference covered, over all soups
  long coverage = 0;        // pixels whose count of covering triangles differs
  long compared = 0;        // pixels both covered with the same count: their depths compared
  long beyond_typical = 0;  // of those, how many differ in depth by more than kTypicalDepth
  float largest_depth = 0.0f;
};

// Where the counts differ, another triangle may be the nearest, so depth is compared only where
// they agree. The bounding box and the scanline interpolate the reference's plane in double
// (weights, or steps down edges and across spans); the reference evaluates it in float from
// its first corner, which for a clipped triangle may lie far off screen: they agree within
// 1e-5. The ray caster's plane goes through the unsnapped corners, which the reference moved
// by up to 1/512 pixel; on a steep triangle that tilts depth by its slope over that distance:
// typically within 1e-4, at most 1e-2.
constexpr float kTypicalDepth = 1e-4f;

SoupDifference compare_soups(Method method) {
  std::mt19937 rng(20261202);
  const Camera camera = test_camera(kWidth, kHeight, 70.0f, 0.5f, 40.0f);
  SoupDifference d;
  for (int s = 0; s < kSoups; ++s) {
    const std::vector<glm::vec3> positions = random_soup(rng);
    const CullMode cull = s % 3 == 0 ? CullMode::back : CullMode::none;
    const pipeline::ReferenceImage expected =
        pipeline::reference_rasterize(positions, camera.view_projection(), cull, kWidth, kHeight);
    const classic::Image image = draw(soup(positions), camera, cull, method, true, kWidth, kHeight);
    for (int i = 0; i < kWidth * kHeight; ++i) {
      d.covered += expected.coverage[i] > 0;
      if (image.hits[i] != expected.coverage[i]) {
        ++d.coverage;
      } else if (expected.coverage[i] > 0) {
        const float delta = std::abs(image.depth[i] - expected.depth[i]);
        ++d.compared;
        d.beyond_typical += delta > kTypicalDepth;
        d.largest_depth = std::max(d.largest_depth, delta);
      }
    }
  }
  std::printf(
      "%s: of %ld covered pixels %ld differ in coverage; of %ld compared, %ld differ in depth by "
      "more than %g (largest %g)\n",
      kMethodNames[static_cast<int>(method)], d.covered, d.coverage, d.compared, d.beyond_typical,
      kTypicalDepth, d.largest_depth);
  return d;
}

// The bounding box works on the same snapped corners with exact edge functions and the same
// top-left rule: coverage is the reference's, pixel for pixel.
TEST(ClassicSoups, BoundingBoxCoverageEqualsTheReference) {
  const SoupDifference d = compare_soups(Method::bounding_box);
  ASSERT_GT(d.covered, 400000);
  EXPECT_EQ(d.coverage, 0);
  EXPECT_LE(d.largest_depth, 1e-5f);
}

// The scanline walk decides a centre against x stepped down the edge in double, exact but for
// rounding, which can matter only for a centre lying exactly on an edge (the shared-edge test
// has 29 and gets them right). None of these soups' pixels differ; the bound leaves room for
// such a centre, not for a wrong rule (a closed span differs on thousands).
TEST(ClassicSoups, ScanlineCoverageDiffersAtMostOnCentresExactlyOnAnEdge) {
  const SoupDifference d = compare_soups(Method::scanline);
  EXPECT_LE(d.coverage, d.covered / 10000);
  EXPECT_LE(d.largest_depth, 1e-5f);
}

// The ray caster does not snap: its edges are the reference's moved by up to 1/512 pixel, so
// centres that close to an edge may differ (74 of 439169 in these soups), and depth differs by
// the snapping's tilt (more than 1e-4 on 0.6% of the pixels compared).
TEST(ClassicSoups, RayPerPixelCoverageDiffersOnlyWhereSnappingMovedAnEdge) {
  const SoupDifference d = compare_soups(Method::ray_per_pixel);
  EXPECT_LE(d.coverage, d.covered / 2000);
  EXPECT_LE(d.beyond_typical, d.compared / 100);
  EXPECT_LE(d.largest_depth, 1e-2f);
}

// Random soups rarely put a pixel centre exactly on an edge, where the fill rule decides. These
// do: every corner lies on the ray through a point of the half-pixel grid (at a random distance),
// so edges run through pixel centres all the time, and half the triangles share an edge with the
// one before.
std::vector<glm::vec3> half_pixel_soup(std::mt19937& rng) {
  std::uniform_int_distribution<int> count(1, 24), x(-10, 2 * kWidth + 10),
      y(-10, 2 * kHeight + 10);
  std::uniform_real_distribution<double> distance(1.0, 20.0);
  std::bernoulli_distribution shares(0.5);
  std::vector<glm::vec3> positions;
  const auto corner = [&] {
    return at_pixel(x(rng) * 0.5, y(rng) * 0.5, kWidth, kHeight, distance(rng), 70.0);
  };
  const int n = count(rng);
  for (int t = 0; t < n; ++t) {
    if (!positions.empty() && shares(rng)) {
      const glm::vec3 a = positions[positions.size() - 1], b = positions[positions.size() - 2];
      positions.insert(positions.end(), {a, b, corner()});
    } else {
      positions.insert(positions.end(), {corner(), corner(), corner()});
    }
  }
  return positions;
}

// On those, the bounding box still equals the reference, pixel for pixel: the same rule decides
// the same ties. The scanline steps x down each edge by adding dx/dy, and the rounding of those
// additions puts x a hair off some crossings that are exactly a centre (503 of 436145 pixels;
// computing x from the edge's top end, the division last, would make it exact). The ray
// caster decides such centres by its own rule, which is not top-left (2406).
TEST(ClassicSoups, OnTheHalfPixelGridTheFillRuleDecidesAsTheReference) {
  std::mt19937 rng(20261203);
  const Camera camera = test_camera(kWidth, kHeight, 70.0f, 0.5f, 40.0f);
  long covered = 0, differ[3] = {0, 0, 0};
  for (int s = 0; s < kSoups; ++s) {
    const std::vector<glm::vec3> positions = half_pixel_soup(rng);
    const CullMode cull = s % 3 == 0 ? CullMode::back : CullMode::none;
    const pipeline::ReferenceImage expected =
        pipeline::reference_rasterize(positions, camera.view_projection(), cull, kWidth, kHeight);
    for (int i = 0; i < kWidth * kHeight; ++i) covered += expected.coverage[i] > 0;
    for (Method method : kMethods) {
      const classic::Image image =
          draw(soup(positions), camera, cull, method, true, kWidth, kHeight);
      for (int i = 0; i < kWidth * kHeight; ++i) {
        differ[static_cast<int>(method)] += image.hits[i] != expected.coverage[i];
      }
    }
  }
  std::printf("half-pixel soups: of %ld covered pixels, %ld, %ld and %ld differ in coverage\n",
              covered, differ[0], differ[1], differ[2]);
  EXPECT_EQ(differ[0], 0);
  EXPECT_LE(differ[1], covered / 500);
  EXPECT_LE(differ[2], covered / 100);
}

// --- The shared edge ----------------------------------------------------------------------

constexpr int kEdgeSize = 40;

// A quad from pixel (4.5, 4.5) to (34.5, 34.5), leaning away (its corners 3 to 5 units from the
// eye), cut along the diagonal through the pixel centres (k + 0.5, k + 0.5): two triangles
// sharing an edge that runs exactly through 29 centres.
Mesh shared_edge_quad() {
  const auto at = [](double x, double y, double distance) {
    return at_pixel(x, y, kEdgeSize, kEdgeSize, distance);
  };
  const glm::vec3 a = at(4.5, 4.5, 3.0), b = at(34.5, 4.5, 4.0), c = at(34.5, 34.5, 5.0),
                  d = at(4.5, 34.5, 4.0);
  return soup({a, b, c, a, c, d});
}

struct EdgeCount {
  int once = 0, twice = 0, never = 0;  // of the 29 centres on the shared edge
  int doubles = 0;                     // pixels hit twice anywhere
  int covered = 0;                     // pixels hit at all
};

EdgeCount count_edge(const classic::Image& image) {
  EdgeCount n;
  for (int k = 5; k <= 33; ++k) {
    const int hits = image.hits[k * kEdgeSize + k];
    n.once += hits == 1;
    n.twice += hits == 2;
    n.never += hits == 0;
  }
  for (std::uint16_t hits : image.hits) {
    n.doubles += hits > 1;
    n.covered += hits > 0;
  }
  return n;
}

classic::Image draw_shared_edge(Method method, bool fill_rule) {
  return draw(shared_edge_quad(), test_camera(kEdgeSize, kEdgeSize), CullMode::none, method,
              fill_rule, kEdgeSize, kEdgeSize);
}

TEST(ClassicSharedEdge, WithTheFillRuleEveryCentreIsCoveredOnce) {
  for (Method method : kMethods) {
    SCOPED_TRACE(kMethodNames[static_cast<int>(method)]);
    const EdgeCount n = count_edge(draw_shared_edge(method, true));
    EXPECT_EQ(n.once, 29);
    EXPECT_EQ(n.doubles, 0);
    // The quad's other edges run through centres too: top and left ones are in, bottom and
    // right ones out, 30 x 30 centres. The ray caster's rule is not top-left: it takes one
    // of each pair of outer edges, which may be another pair.
    if (method == Method::ray_per_pixel) {
      EXPECT_NEAR(n.covered, 30 * 30, 2 * 31);
    } else {
      EXPECT_EQ(n.covered, 30 * 30);
    }
  }
}

// Without the rule the bounding box and the scanline take every centre on the edge twice; the
// textbook ray test decides each from two planes and two hit points, so rounding gives some
// centres to both triangles and some to neither.
TEST(ClassicSharedEdge, WithoutTheFillRuleTheEdgeIsHitTwiceOrCracks) {
  for (Method method : {Method::bounding_box, Method::scanline}) {
    SCOPED_TRACE(kMethodNames[static_cast<int>(method)]);
    const EdgeCount n = count_edge(draw_shared_edge(method, false));
    EXPECT_EQ(n.twice, 29);
  }
  const EdgeCount ray = count_edge(draw_shared_edge(Method::ray_per_pixel, false));
  std::printf("textbook ray test on the shared edge: %d once, %d twice, %d never\n", ray.once,
              ray.twice, ray.never);
  EXPECT_GT(ray.twice + ray.never, 0);
  EXPECT_EQ(ray.once + ray.twice + ray.never, 29);
}

// --- Pictures: the chapters' scenes against facet's own render ----------------------------

constexpr int kPictureWidth = 240;
constexpr int kPictureHeight = 135;
const char* const kBunny = "/usr/share/glmark2/models/bunny.obj";  // Debian's glmark2-data

// The scene and camera each chapter draws.
struct Picture {
  Scene scene;
  Camera camera;
};

Picture picture_scene(const std::string& name) {
  Picture p;
  if (name == "triangle") {
    p.scene = classic::make_triangle_scene();
  } else if (name == "shapes") {
    p.scene = make_builtin_scene("shapes");
  } else {
    ImportOptions options;
    options.warn = [](const std::string&) {};
    p.scene = import_scene(kBunny, options);
  }
  const float aspect = static_cast<float>(kPictureWidth) / kPictureHeight;
  p.camera = scene_camera(p.scene, aspect);
  p.camera.aspect = aspect;
  return p;
}

// facet's normals view of the same scene: what the classic rasterizers show.
Framebuffer facet_render(const Picture& p) {
  Scene scene = p.scene;
  for (Material& m : scene.materials) {
    m.shading = ShadingModel::normals;
    m.alpha_mode = AlphaMode::opaque;
  }
  scene.lighting.environment.show_as_background = false;
  RenderSettings settings;
  settings.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  Renderer renderer(settings);
  Framebuffer framebuffer(kPictureWidth, kPictureHeight);
  renderer.begin_frame(p.camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(framebuffer);
  return framebuffer;
}

void expect_matches_picture(const Framebuffer& framebuffer, const std::string& name) {
  const std::string path =
      (std::filesystem::path(::testing::TempDir()) / ("classic_" + name + ".png")).string();
  write_image(framebuffer, path);
  expect_matches_golden_in(FACET_CLASSIC_PICTURE_DIR, path, name);
}

// Against facet, per scene: pixels covered by one and not the other (silhouettes), and pixels
// covered by both whose color differs by more than 2 levels. Both interpolate the same world
// normal perspective-correct, so colors agree but where the two take different triangles: at
// silhouettes, where facet's snapped edges and the ray caster's unsnapped ones part, and where
// two surfaces meet at almost the same depth. Measured: no silhouette pixel differs in any of
// the nine pictures, one color (the ray caster's shapes); the bounds, per 240 x 135 picture,
// leave room for a few such pixels, not for a wrong interpolation (affine colors on the
// leaning triangle differ on thousands).
struct SceneBound {
  const char* scene;
  int silhouette;  // pixels
  int color;       // pixels
};
constexpr SceneBound kSceneBounds[] = {{"triangle", 4, 4}, {"shapes", 12, 12}, {"bunny", 24, 24}};

class ClassicPictures : public ::testing::TestWithParam<SceneBound> {};

TEST_P(ClassicPictures, MatchFacetAndTheirGoldens) {
  const SceneBound bound = GetParam();
  if (std::string(bound.scene) == "bunny") {
    FACET_REQUIRE_PACKAGE(std::filesystem::exists(kBunny), "the bunny needs glmark2-data");
  }
  const Picture p = picture_scene(bound.scene);
  const Framebuffer facet_image = facet_render(p);
  expect_matches_picture(facet_image, std::string("facet_") + bound.scene);
  for (Method method : kMethods) {
    const std::string name = kMethodNames[static_cast<int>(method)];
    SCOPED_TRACE(name);
    classic::Image image(kPictureWidth, kPictureHeight);
    classic::draw_scene(p.scene, p.camera, {method, true}, image);
    int silhouette = 0, color = 0;
    for (int i = 0; i < kPictureWidth * kPictureHeight; ++i) {
      const bool ours = image.depth[i] < 1.0f, theirs = facet_image.depth()[i] < 1.0f;
      silhouette += ours != theirs;
      if (!ours || !theirs) continue;
      for (int c = 0; c < 3; ++c) {
        if (std::abs(image.rgba[i * 4 + c] - facet_image.rgba8()[i * 4 + c]) > 2) {
          ++color;
          break;
        }
      }
    }
    std::printf("%s %s: %d silhouette pixels differ, %d colors\n", name.c_str(), bound.scene,
                silhouette, color);
    EXPECT_LE(silhouette, bound.silhouette);
    EXPECT_LE(color, bound.color);
    expect_matches_picture(classic::to_framebuffer(image), name + "_" + bound.scene);
  }
}

INSTANTIATE_TEST_SUITE_P(Classic, ClassicPictures, ::testing::ValuesIn(kSceneBounds),
                         [](const ::testing::TestParamInfo<SceneBound>& param_info) {
                           return std::string(param_info.param.scene);
                         });

// The shared-edge pictures: how many triangles covered each pixel (black none, grey one, red
// two), each pixel drawn 6 x 6.
Framebuffer hit_picture(const classic::Image& image) {
  constexpr int kScale = 6;
  Framebuffer framebuffer(kEdgeSize * kScale, kEdgeSize * kScale);
  for (int y = 0; y < kEdgeSize * kScale; ++y) {
    for (int x = 0; x < kEdgeSize * kScale; ++x) {
      const int hits = image.hits[(y / kScale) * kEdgeSize + x / kScale];
      const bool grid = x % kScale == 0 || y % kScale == 0;  // pixel borders, faintly
      std::uint8_t rgb[3] = {0, 0, 0};
      if (hits == 1) rgb[0] = rgb[1] = rgb[2] = 150;
      if (hits >= 2) rgb[0] = 230, rgb[1] = 40, rgb[2] = 40;
      std::uint8_t* out =
          &framebuffer.rgba8()[(static_cast<std::size_t>(y) * kEdgeSize * kScale + x) * 4];
      for (int c = 0; c < 3; ++c)
        out[c] = grid ? static_cast<std::uint8_t>(rgb[c] * 3 / 4 + 16) : rgb[c];
      out[3] = 255;
    }
  }
  return framebuffer;
}

TEST(ClassicSharedEdge, PicturesMatchTheirGoldens) {
  for (Method method : kMethods) {
    const std::string name = kMethodNames[static_cast<int>(method)];
    expect_matches_picture(hit_picture(draw_shared_edge(method, true)), name + "_shared_edge");
    expect_matches_picture(hit_picture(draw_shared_edge(method, false)),
                           name + "_shared_edge_no_rule");
  }
}

}  // namespace
}  // namespace facet::test
