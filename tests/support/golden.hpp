// Golden-image comparison for image tests: a render against tests/golden/<name>.png (or another
// folder of goldens, such as docs/pipeline/) with a stated tolerance, a diff image on failure,
// and FACET_UPDATE_GOLDENS=1 to rewrite goldens.
#pragma once

#include <string>

namespace facet::test {

// A channel may differ from the golden by at most 2 levels (of 255), and at most 0.1% of pixels
// (230 of 640x360) may differ by more. That absorbs a reordered float operation or a different
// rounding in a later optimisation (which moves a shade by one level, or an edge pixel or two),
// while any visible change - a moved edge, a changed light, a missing object - fails.
struct Tolerance {
  int max_channel_delta;
  double max_outlier_fraction;
};
inline constexpr Tolerance kGoldenTolerance{2, 0.001};

// Compares the PNG at rendered_path with tests/golden/<golden_name>.png (same size required)
// and adds a gtest failure describing the difference; with FACET_UPDATE_GOLDENS=1 it copies
// the render over the golden instead and skips the test.
void expect_matches_golden(const std::string& rendered_path, const std::string& golden_name,
                           Tolerance tolerance = kGoldenTolerance);

// The same with the golden at <golden_dir>/<golden_name>.png: the pictures of docs/pipeline.md
// are goldens in docs/pipeline/ (tests/docs_pictures_test.cpp).
void expect_matches_golden_in(const std::string& golden_dir, const std::string& rendered_path,
                              const std::string& golden_name,
                              Tolerance tolerance = kGoldenTolerance);

}  // namespace facet::test
