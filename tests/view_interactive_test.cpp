// `facet view` driven like a person would: the viewer runs on a fresh Xvfb display and real key
// and mouse events reach it through xdotool (XTEST). F12 saves a screenshot and logs the camera,
// Shift+F12 the whole window; the tests read both and check what each input did.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/render_helpers.hpp"
#include "support/required_package.hpp"

namespace facet::test {
namespace {

namespace fs = std::filesystem;

bool have_tools() {
  return std::system("command -v xvfb-run >/dev/null 2>&1 && command -v xdotool >/dev/null 2>&1") ==
         0;
}

// Shell functions for the scripts, run in the test's directory on the virtual display:
// - start_view ARGS: starts `facet view ARGS` (stdout to view.log), waits for its window,
//   focuses it and takes screenshot 1;
// - shot: F12, then waits until the screenshot is written;
// - window_shot: Shift+F12 (the window as shown), then waits likewise;
// - wait_size W H: waits until the window has that size;
// - stop_view: Esc, then waits for the viewer to exit.
// Every wait polls the log with a generous timeout instead of sleeping blindly.
const char* const kPrelude = R"sh(
set -eu
wait_log() {  # wait_log COUNT PATTERN
  for i in $(seq 1 600); do
    if [ "$(grep -c -- "$2" view.log || true)" -ge "$1" ]; then return 0; fi
    if ! kill -0 "$VIEW_PID" 2>/dev/null; then echo "viewer exited early" >&2; cat view.err >&2; exit 1; fi
    sleep 0.05
  done
  echo "timed out waiting for $1 x '$2'" >&2; cat view.log view.err >&2; exit 1
}
start_view() {
  "$FACET" view "$@" >view.log 2>view.err &
  VIEW_PID=$!
  WID=$(timeout 60 xdotool search --sync --onlyvisible --name '^facet view$' | head -n 1)
  xdotool windowfocus --sync "$WID"
  shot  # the first frame is up once a screenshot of it is
}
shot() {
  local n=$(( $(grep -c 'saved facet-screenshot' view.log || true) + 1 ))
  xdotool key F12
  wait_log "$n" 'saved facet-screenshot'
}
window_shot() {
  local n=$(( $(grep -c 'saved facet-window' view.log || true) + 1 ))
  xdotool key shift+F12
  wait_log "$n" 'saved facet-window'
}
wait_size() {  # wait_size W H: until the X server has the window at that size
  for i in $(seq 1 200); do
    eval "$(xdotool getwindowgeometry --shell "$WID")"
    if [ "$WIDTH" = "$1" ] && [ "$HEIGHT" = "$2" ]; then sleep 0.2; return 0; fi
    sleep 0.05
  done
  echo "the window never became $1x$2 (it is ${WIDTH}x${HEIGHT})" >&2; exit 1
}
stop_view() {
  xdotool key Escape
  for i in $(seq 1 200); do kill -0 "$VIEW_PID" 2>/dev/null || break; sleep 0.05; done
  wait "$VIEW_PID"
}
)sh";

struct Session {
  fs::path dir;
  CommandResult result;
  std::string log;  // the viewer's stdout

  fs::path file(const std::string& name) const { return dir / name; }
  Rgba8Image image(const std::string& name) const { return read_png(file(name).string()); }
};

// Runs `script` after the prelude on a fresh 1920x1080 display, in a fresh directory.
Session run_session(const std::string& name, const std::string& script) {
  Session s;
  s.dir = fresh_test_dir("facet_view_input_", name);
  std::ofstream(s.dir / "script.sh") << kPrelude << script;
  std::string command = "cd '" + s.dir.string() + "' && ";
  command += "FACET='" + std::string(FACET_CLI) + "' ";
  command += "ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" ";
  command += "timeout 120 xvfb-run -a -s '-screen 0 1920x1080x24' bash script.sh";
  s.result = run_command(command);
  std::ifstream log(s.dir / "view.log");
  std::stringstream text;
  text << log.rdbuf();
  s.log = text.str();
  return s;
}

// What the viewer logged for its N-th screenshot (1-based).
struct ShotLog {
  int render_w = 0, render_h = 0, window_w = 0, window_h = 0;
  glm::vec3 eye{0.0f}, forward{0.0f};
  float fov = 0.0f;
  std::string mode;
  std::string shading;  // "material" or a shading model's name
  int threads = -1;
  int msaa = -1;
  std::string camera;  // "orbit" or "first person"
  std::string sound;   // "on", "muted" or "none" (a scene without sound)
};
ShotLog shot_log(const Session& s, int n) {
  std::regex line(
      "saved facet-screenshot-" + std::to_string(n) +
      R"(\.png \(render (\d+)x(\d+), window (\d+)x(\d+), eye ([-\d.]+),([-\d.]+),)"
      R"(([-\d.]+), forward ([-\d.]+),([-\d.]+),([-\d.]+), fov ([\d.]+), mode ([^,]+), )"
      R"(shading ([^,]+), threads (\d+), msaa (\d+), camera ([^,]+), sound ([^)]+)\))");
  std::smatch m;
  ShotLog out;
  if (!std::regex_search(s.log, m, line)) {
    ADD_FAILURE() << "no log line for screenshot " << n << " in:\n" << s.log;
    return out;
  }
  out.render_w = std::stoi(m[1]), out.render_h = std::stoi(m[2]);
  out.window_w = std::stoi(m[3]), out.window_h = std::stoi(m[4]);
  out.eye = {std::stof(m[5]), std::stof(m[6]), std::stof(m[7])};
  out.forward = {std::stof(m[8]), std::stof(m[9]), std::stof(m[10])};
  out.fov = std::stof(m[11]);
  out.mode = m[12];
  out.shading = m[13];
  out.threads = std::stoi(m[14]);
  out.msaa = std::stoi(m[15]);
  out.camera = m[16];
  out.sound = m[17];
  return out;
}

std::string shot_name(int n) { return "facet-screenshot-" + std::to_string(n) + ".png"; }

// Fraction of pixels whose largest channel difference is above 8 levels.
double changed_fraction(const Rgba8Image& a, const Rgba8Image& b) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  std::size_t changed = 0, n = std::min(a.pixels.size(), b.pixels.size()) / 4;
  for (std::size_t p = 0; p < n; ++p) {
    int delta = 0;
    for (int c = 0; c < 3; ++c)
      delta = std::max(delta, std::abs(a.pixels[p * 4 + c] - b.pixels[p * 4 + c]));
    if (delta > 8) ++changed;
  }
  return n ? static_cast<double>(changed) / n : 0.0;
}

// The rows and columns where two images of one size differ by more than 8 in a channel (top
// > bottom when they do not).
struct ChangedBox {
  int top, bottom, left, right;
};
ChangedBox changed_box(const Rgba8Image& a, const Rgba8Image& b) {
  ChangedBox box{a.height, -1, a.width, -1};
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 4;
      int delta = 0;
      for (int c = 0; c < 3; ++c)
        delta = std::max(delta, std::abs(a.pixels[i + c] - b.pixels[i + c]));
      if (delta <= 8) continue;
      box.top = std::min(box.top, y), box.bottom = std::max(box.bottom, y);
      box.left = std::min(box.left, x), box.right = std::max(box.right, x);
    }
  }
  return box;
}

// Where the F1 help changed the window: between its first window shot (without the help) and
// its second (with it), both expected width x height. An empty box (top > bottom) if the sizes
// are wrong, after saying so.
ChangedBox help_box(const Session& s, int width, int height) {
  const Rgba8Image plain = s.image("facet-window-1.png"), help = s.image("facet-window-2.png");
  EXPECT_EQ(help.width, width);
  EXPECT_EQ(help.height, height);
  if (help.width != width || help.height != height || plain.pixels.size() != help.pixels.size())
    return {height, -1, width, -1};
  return changed_box(plain, help);
}

bool is_black_row(const Rgba8Image& image, int y) {
  for (int x = 0; x < image.width; ++x) {
    const std::uint8_t* p = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
    if (p[0] > 2 || p[1] > 2 || p[2] > 2) return false;
  }
  return true;
}

// The islands at a fixed time, small, with no overlay: only the input changes the image.
const std::string kIslands = "start_view --scene islands --size 320x180 --time 3 --overlay off\n";

#define REQUIRE_TOOLS() FACET_REQUIRE_PACKAGE(have_tools(), "xvfb-run or xdotool is not installed")

TEST(ViewInput, WMovesTheCameraForward) {
  REQUIRE_TOOLS();
  Session s = run_session("w", kIslands +
                                   "xdotool keydown w; sleep 1; xdotool keyup w\n"
                                   "shot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  ShotLog before = shot_log(s, 1), after = shot_log(s, 2);
  glm::vec3 moved = after.eye - before.eye;
  glm::vec3 heading = glm::normalize(glm::vec3(before.forward.x, 0.0f, before.forward.z));
  // Forward along the level heading, not sideways, not up; the view direction is unchanged.
  EXPECT_GT(glm::dot(moved, heading), 0.5f)
      << "moved " << moved.x << "," << moved.y << "," << moved.z;
  EXPECT_LT(glm::length(moved - heading * glm::dot(moved, heading)), 1e-2f);
  EXPECT_LT(glm::length(after.forward - before.forward), 1e-3f);
  EXPECT_GT(changed_fraction(s.image(shot_name(1)), s.image(shot_name(2))), 0.05);
}

TEST(ViewInput, MouseMotionTurnsTheCamera) {
  REQUIRE_TOOLS();
  // A click captures the mouse (relative mode); then motion to the right turns right.
  Session s =
      run_session("mouse", kIslands +
                               "xdotool mousemove --window \"$WID\" 160 90 click 1\n"
                               "sleep 0.3\n"
                               "for i in 1 2 3 4 5 6; do xdotool mousemove_relative -- 20 0;"
                               " sleep 0.05; done\n"
                               "sleep 0.3\nshot\nxdotool key Escape\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  ShotLog before = shot_log(s, 1), after = shot_log(s, 2);
  EXPECT_LT(glm::length(after.eye - before.eye), 1e-3f);  // turned, not moved
  // Turning right: the new forward leans toward the old view's right (forward x up).
  glm::vec3 right = glm::normalize(glm::cross(before.forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  float turn_right = glm::dot(after.forward, right);
  EXPECT_GT(turn_right, 0.05f) << "forward before " << before.forward.x << "," << before.forward.z
                               << " after " << after.forward.x << "," << after.forward.z;
  EXPECT_GT(changed_fraction(s.image(shot_name(1)), s.image(shot_name(2))), 0.05);
}

TEST(ViewInput, ModelsStartInOrbitWhereTheWheelZoomsAndTabSwitches) {
  REQUIRE_TOOLS();
  const std::string model = "/usr/share/glmark2/models/bunny.obj";
  FACET_REQUIRE_PACKAGE(fs::exists(model), model << " is missing (glmark2-data)");
  Session s = run_session("orbit", "start_view '" + model +
                                       "' --size 320x180 --overlay off\n"
                                       "xdotool mousemove --window \"$WID\" 160 90\n"
                                       "xdotool click 4 click 4 click 4\nsleep 0.3\nshot\n"
                                       "xdotool key Tab\nshot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  ShotLog start = shot_log(s, 1), zoomed = shot_log(s, 2), switched = shot_log(s, 3);
  EXPECT_EQ(start.camera, "orbit");
  // Three wheel notches toward the model: the eye moves along the view direction, which stays.
  glm::vec3 moved = zoomed.eye - start.eye;
  EXPECT_GT(glm::dot(moved, start.forward), 0.0f);
  EXPECT_LT(glm::length(zoomed.forward - start.forward), 1e-3f);
  EXPECT_GT(changed_fraction(s.image(shot_name(1)), s.image(shot_name(2))), 0.02);
  // Tab: first person from the same pose, no jump.
  EXPECT_EQ(switched.camera, "first person");
  EXPECT_LT(glm::length(switched.eye - zoomed.eye), 1e-3f);
}

TEST(ViewInput, OrbitLeftDragTurnsAroundTheTargetAndMiddleDragPans) {
  REQUIRE_TOOLS();
  const std::string model = "/usr/share/glmark2/models/bunny.obj";
  FACET_REQUIRE_PACKAGE(fs::exists(model), model << " is missing (glmark2-data)");
  Session s = run_session(
      "orbit_drag",
      "start_view '" + model +
          "' --size 320x180 --overlay off\n"
          "xdotool mousemove --window \"$WID\" 100 90 mousedown 1\n"
          "for i in 1 2 3 4 5; do xdotool mousemove_relative -- 20 0; sleep 0.05; done\n"
          "xdotool mouseup 1\nsleep 0.3\nshot\n"
          "xdotool mousemove --window \"$WID\" 100 90 mousedown 2\n"
          "for i in 1 2 3 4 5; do xdotool mousemove_relative -- 20 0; sleep 0.05; done\n"
          "xdotool mouseup 2\nsleep 0.3\nshot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  ShotLog start = shot_log(s, 1), orbited = shot_log(s, 2), panned = shot_log(s, 3);
  // Orbiting: the view turned, and both views meet at the same target at the same distance
  // d (eye + forward * d); solve for d along x and z and check the two agree.
  EXPECT_GT(glm::length(orbited.forward - start.forward), 0.05f);
  glm::vec3 df = start.forward - orbited.forward, de = orbited.eye - start.eye;
  float d = glm::dot(de, df) / glm::dot(df, df);
  glm::vec3 miss = (start.eye + start.forward * d) - (orbited.eye + orbited.forward * d);
  EXPECT_LT(glm::length(miss), 1e-2f * d) << "d " << d;
  // Panning: the view direction stays, the eye slides across it.
  EXPECT_LT(glm::length(panned.forward - orbited.forward), 1e-3f);
  glm::vec3 slide = panned.eye - orbited.eye;
  EXPECT_GT(glm::length(slide), 1e-3f);
  EXPECT_LT(std::abs(glm::dot(slide, orbited.forward)), 1e-2f * glm::length(slide) + 1e-4f);
}

TEST(ViewInput, IslandsHaveSoundThatMTogglesAndNoDeviceCostsOneWarning) {
  REQUIRE_TOOLS();
  Session s =
      run_session("sound", kIslands + "xdotool key m\nshot\nxdotool key m\nshot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  EXPECT_EQ(shot_log(s, 1).sound, "on");
  EXPECT_EQ(shot_log(s, 2).sound, "muted");
  EXPECT_EQ(shot_log(s, 3).sound, "on");
  // With no audio device (CI) SoundScene says so in one line and the viewer runs silently.
  std::ifstream err(s.file("view.err"));
  std::string text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_LE(std::count(text.begin(), text.end(), '\n'), 1) << text;
}

TEST(ViewInput, F2CyclesTheRenderMode) {
  REQUIRE_TOOLS();
  Session s =
      run_session("f2", kIslands + "xdotool key F2\nshot\nxdotool key F2\nshot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  EXPECT_EQ(shot_log(s, 1).mode, "shaded");
  EXPECT_EQ(shot_log(s, 2).mode, "wireframe");
  EXPECT_EQ(shot_log(s, 3).mode, "wire overlay");
  EXPECT_GT(changed_fraction(s.image(shot_name(1)), s.image(shot_name(2))), 0.3);
}

TEST(ViewInput, F3F4ChangeTheFieldOfViewF7TheShadingF8TheThreads) {
  REQUIRE_TOOLS();
  Session s = run_session("f3f4f7f8", kIslands +
                                          "xdotool key F4\nshot\nxdotool key F3 F3\nshot\n"
                                          "xdotool key F7\nshot\nxdotool key F8\nshot\n"
                                          "stop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  float fov = shot_log(s, 1).fov;
  EXPECT_FLOAT_EQ(shot_log(s, 2).fov, fov + 5.0f);
  EXPECT_FLOAT_EQ(shot_log(s, 3).fov, fov - 5.0f);
  // A wider view shows more: the same scene, smaller.
  EXPECT_GT(changed_fraction(s.image(shot_name(1)), s.image(shot_name(2))), 0.2);
  EXPECT_EQ(shot_log(s, 3).shading, "material");
  EXPECT_EQ(shot_log(s, 4).shading, "unlit");
  EXPECT_GT(changed_fraction(s.image(shot_name(3)), s.image(shot_name(4))), 0.2);
  EXPECT_EQ(shot_log(s, 4).threads, 0);  // --threads default: all cores
  EXPECT_EQ(shot_log(s, 5).threads, 1);  // F8 from "all" starts again at 1
  // The image is the same for any thread count (above the change panel at the bottom).
  Rgba8Image all = s.image(shot_name(4)), one = s.image(shot_name(5));
  all.pixels.resize(320 * 130 * 4), one.pixels.resize(320 * 130 * 4);
  EXPECT_EQ(changed_fraction(all, one), 0.0);
}

// The help is drawn at the window's resolution, not into the frame: at a 320x180 render
// resolution in a 1280x720 window it is whole (the frame could not hold its rows) and centred,
// with rows of the picture above and below it; the frame itself (F12) is left as it was.
TEST(ViewInput, F1ShowsTheWholeHelpPanelInTheMiddleOfTheWindow) {
  REQUIRE_TOOLS();
  Session s = run_session("f1", kIslands +
                                    "xdotool windowsize --sync \"$WID\" 1280 720\n"
                                    "wait_size 1280 720\nwindow_shot\n"
                                    "xdotool key F1\nsleep 3\nwindow_shot\nshot\n"
                                    "xdotool key F1\nsleep 3\nwindow_shot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  const Rgba8Image plain = s.image("facet-window-1.png");
  const auto [top, bottom, left, right] = help_box(s, 1280, 720);
  ASSERT_GE(bottom, top) << "F1 changed nothing in the window";
  EXPECT_GT(bottom - top, 300);  // more rows than a 180-pixel frame has: window pixels
  EXPECT_GT(top, 20);            // whole: picture rows above and below it
  EXPECT_LT(bottom, 700);
  EXPECT_LT(std::abs((top + bottom) / 2 - 360), 8);  // centred
  EXPECT_LT(std::abs((left + right) / 2 - 640), 8);
  EXPECT_EQ(changed_fraction(plain, s.image("facet-window-3.png")), 0.0);  // F1 again hides it
  EXPECT_EQ(changed_fraction(s.image(shot_name(1)), s.image(shot_name(2))),
            0.0);  // not in the frame
}

// A small render resolution opens a window big enough for the help: 320x180 opens at twice
// that, where F1 shows the whole panel with the picture all around it.
TEST(ViewInput, SmallRendersOpenAWindowTheHelpFits) {
  REQUIRE_TOOLS();
  Session s = run_session("f1_small", kIslands +
                                          "window_shot\nxdotool key F1\nsleep 3\n"
                                          "window_shot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  const auto [top, bottom, left, right] = help_box(s, 640, 360);
  ASSERT_GE(bottom, top) << "F1 changed nothing in the window";
  EXPECT_GT(bottom - top, 250);  // the whole key table
  EXPECT_GT(top, 0);             // and not cut off: picture rows above and below it
  EXPECT_LT(bottom, 360 - 1);
  EXPECT_GT(left, 0);  // and picture columns left and right of it
  EXPECT_LT(right, 640 - 1);
}

// The whole multiple stops at the display: 500x100 would need 2000x400 on a 1920-pixel screen,
// so it opens at three times, 1500 wide, and as tall as the smallest window.
TEST(ViewInput, AWindowOpensNoWiderThanTheDisplay) {
  REQUIRE_TOOLS();
  Session s = run_session("wide",
                          "start_view --scene shapes --size 500x100 --overlay off\n"
                          "stop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  EXPECT_EQ(shot_log(s, 1).window_w, 1500);
  EXPECT_EQ(shot_log(s, 1).window_h, 360);
}

TEST(ViewInput, F6RaisesAndF5LowersTheRenderResolution) {
  REQUIRE_TOOLS();
  Session s =
      run_session("f6", kIslands + "xdotool key F6\nshot\nxdotool key F5\nshot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  Rgba8Image small = s.image(shot_name(1)), large = s.image(shot_name(2)),
             back = s.image(shot_name(3));
  EXPECT_EQ(small.width, 320);
  EXPECT_EQ(small.height, 180);
  EXPECT_EQ(large.width, 640);
  EXPECT_EQ(large.height, 360);
  EXPECT_EQ(back.width, 320);
  EXPECT_EQ(shot_log(s, 2).render_w, 640);
}

// Xvfb has no window manager, so nothing honours _NET_WM_STATE_FULLSCREEN and the X window keeps
// its size; what F11 changes and this test sees is SDL's window: its size becomes the display's
// and the window's picture (Shift+F12) is drawn at that size, and F11 again restores both.
TEST(ViewInput, F11TogglesFullscreen) {
  REQUIRE_TOOLS();
  Session s = run_session("f11", kIslands +
                                     "xdotool key F11\nshot\nwindow_shot\n"
                                     "xdotool key F11\nshot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  EXPECT_EQ(shot_log(s, 1).window_w, 640);   // a 320x180 render opens a 640x360 window
  EXPECT_EQ(shot_log(s, 2).window_w, 1920);  // the whole 1920x1080 screen
  EXPECT_EQ(shot_log(s, 2).window_h, 1080);
  EXPECT_EQ(shot_log(s, 3).window_w, 640);  // and back
  Rgba8Image window = s.image("facet-window-1.png");
  EXPECT_EQ(window.width, 1920);
  EXPECT_EQ(window.height, 1080);
  EXPECT_EQ(shot_log(s, 2).render_w, 320);  // the render resolution does not follow the window
}

TEST(ViewInput, LetterboxBarsWhenTheWindowAspectDiffers) {
  REQUIRE_TOOLS();
  // A square window showing a 16:9 frame: 640 wide means a 360-pixel picture, 140-pixel bars.
  Session s = run_session("letterbox", kIslands +
                                           "xdotool windowsize --sync \"$WID\" 640 640\n"
                                           "wait_size 640 640\nwindow_shot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  Rgba8Image window = s.image("facet-window-1.png");
  ASSERT_EQ(window.width, 640);
  ASSERT_EQ(window.height, 640);
  for (int y : {0, 60, 135, 505, 580, 639}) EXPECT_TRUE(is_black_row(window, y)) << "row " << y;
  for (int y : {145, 320, 495}) EXPECT_FALSE(is_black_row(window, y)) << "row " << y;
}

#if FACET_HAS_GL
// B switches facet's renderer -> its OpenGL twin -> their difference -> facet: the twin's
// frame is facet's to within edge pixels, the difference view is dark where they agree, and
// each screenshot's log line names the backend that drew it.
TEST(ViewInput, BTogglesTheOpenGLTwinAndTheDifference) {
  REQUIRE_TOOLS();
  const std::string b = "xdotool key b\nshot\n";
  Session s =
      run_session("backend", "start_view --scene shapes --size 320x180 --overlay off --msaa 1\n" +
                                 b + b + b + "stop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  const char* const backends[] = {"facet", "gl", "difference", "facet"};
  for (int n = 1; n <= 4; ++n) {
    const std::string line = shot_name(n) + " drawn by backend " + backends[n - 1];
    EXPECT_NE(s.log.find(line), std::string::npos) << line << " not in:\n" << s.log;
  }
  EXPECT_NE(s.log.find("drawn by backend gl, OpenGL llvmpipe"), std::string::npos) << s.log;
  // The top 130 rows: the change panel ("backend: gl") covers the bottom of the frame.
  auto top = [](Rgba8Image image) {
    image.height = 130;
    image.pixels.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    return image;
  };
  const Rgba8Image facet = top(s.image(shot_name(1))), gl = top(s.image(shot_name(2)));
  const Rgba8Image difference = top(s.image(shot_name(3))), again = top(s.image(shot_name(4)));
  EXPECT_LT(changed_fraction(facet, gl), 0.005);
  EXPECT_EQ(changed_fraction(facet, again), 0.0);
  // Dark where the two agree: an 8x amplified difference above 64 is 8 levels apart.
  std::size_t bright = 0;
  for (std::size_t i = 0; i < difference.pixels.size(); i += 4) {
    bright +=
        std::max({difference.pixels[i], difference.pixels[i + 1], difference.pixels[i + 2]}) > 64;
  }
  EXPECT_LT(bright, difference.pixels.size() / 4 / 200);
  EXPECT_GT(changed_fraction(facet, difference), 0.5);  // it is not the picture
}
#endif

TEST(ViewInput, F9ShowsTheOverlayAtTheLeft) {
  REQUIRE_TOOLS();
  Session s = run_session("f9", kIslands + "xdotool key F9\nsleep 3\nshot\nstop_view\n");
  ASSERT_EQ(s.result.exit_code, 0) << s.result.stderr_text;
  Rgba8Image plain = s.image(shot_name(1)), overlay = s.image(shot_name(2));
  // The statistics panel covers the left of the frame (at 320x180 about 200 pixels wide); the
  // right quarter is untouched, and the change panel ("overlay: on") is gone after two seconds.
  std::size_t left = 0, right = 0;
  for (int y = 0; y < 180; ++y) {
    for (int x = 0; x < 80; ++x) {
      for (auto [px, count] : {std::pair{x, &left}, {x + 240, &right}}) {
        std::size_t i = (static_cast<std::size_t>(y) * 320 + px) * 4;
        if (std::abs(plain.pixels[i] - overlay.pixels[i]) > 8) ++*count;
      }
    }
  }
  EXPECT_GT(left, 2000u);
  EXPECT_EQ(right, 0u);
}

}  // namespace
}  // namespace facet::test
