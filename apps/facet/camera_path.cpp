// Camera paths (see camera_path.hpp for the file format).
#include "camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "facet/error.hpp"

namespace facet::cli {
namespace {

constexpr int kFields = 6;  // t x y z yaw pitch

[[noreturn]] void fail(const std::string& name, int line, const std::string& problem) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict) on "literal" + std::string here.
  std::string message = name;
  message += ':';
  message += std::to_string(line);
  message += ": ";
  message += problem;
  throw Error(message);
}

// One key from a line with its comment removed; false if the line is blank.
bool parse_key(const std::string& text, const std::string& name, int line, CameraKey& key) {
  std::istringstream words(text);
  std::vector<double> values;
  std::string word;
  while (words >> word) {
    char* end = nullptr;
    double v = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0' || !std::isfinite(v)) {
      std::string problem = "'";
      problem += word;
      problem += "' is not a number";
      fail(name, line, problem);
    }
    values.push_back(v);
  }
  if (values.empty()) return false;
  if (values.size() != kFields) {
    std::string problem = "expected 6 numbers (t x y z yaw pitch), got ";
    problem += std::to_string(values.size());
    fail(name, line, problem);
  }
  // Beyond this, a position's float spacing passes one unit and the camera's unit step from
  // eye to target is lost; times and angles get the same sanity bound.
  constexpr double kLargest = 1e6;
  for (double v : values) {
    if (std::abs(v) > kLargest) fail(name, line, "values must lie within +-1e6");
  }
  if (!(std::abs(values[5]) < 90.0)) fail(name, line, "pitch must be inside (-90, 90) degrees");
  key.time = values[0];
  key.pose.position = glm::vec3(values[1], values[2], values[3]);
  key.pose.yaw_degrees = static_cast<float>(values[4]);
  key.pose.pitch_degrees = static_cast<float>(values[5]);
  return true;
}

// Uniform Catmull-Rom between p1 and p2 at u in [0, 1], with neighbours p0 and p3.
template <class T>
T catmull_rom(const T& p0, const T& p1, const T& p2, const T& p3, float u) {
  float u2 = u * u, u3 = u2 * u;
  return 0.5f * ((2.0f * p1) + (p2 - p0) * u + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * u2 +
                 (3.0f * p1 - p0 - 3.0f * p2 + p3) * u3);
}

}  // namespace

CameraPath CameraPath::load(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw Error(path + ": cannot open the camera path");
  std::stringstream text;
  text << file.rdbuf();
  if (file.bad()) throw Error(path + ": cannot read the camera path");
  return parse(text.str(), path);
}

CameraPath CameraPath::parse(const std::string& text, const std::string& name) {
  CameraPath path;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    line = line.substr(0, line.find('#'));
    CameraKey key;
    if (!parse_key(line, name, number, key)) continue;
    if (!path.keys_.empty() && !(key.time > path.keys_.back().time)) {
      std::string problem = "times must increase (";
      problem += std::to_string(key.time) + " after " + std::to_string(path.keys_.back().time);
      fail(name, number, problem + ")");
    }
    path.keys_.push_back(key);
  }
  if (path.keys_.empty()) throw Error(name + ": no camera keys (lines of t x y z yaw pitch)");
  return path;
}

FirstPersonCamera CameraPath::at(double seconds) const {
  if (seconds <= keys_.front().time) return keys_.front().pose;
  if (seconds >= keys_.back().time) return keys_.back().pose;
  // The segment [i, i + 1] holding `seconds`; its neighbours clamp at the ends.
  auto after = std::upper_bound(keys_.begin(), keys_.end(), seconds,
                                [](double t, const CameraKey& k) { return t < k.time; });
  std::size_t i = static_cast<std::size_t>(after - keys_.begin()) - 1;
  std::size_t last = keys_.size() - 1;
  const FirstPersonCamera& p0 = keys_[i == 0 ? 0 : i - 1].pose;
  const FirstPersonCamera& p1 = keys_[i].pose;
  const FirstPersonCamera& p2 = keys_[i + 1].pose;
  const FirstPersonCamera& p3 = keys_[std::min(i + 2, last)].pose;
  float u = static_cast<float>((seconds - keys_[i].time) / (keys_[i + 1].time - keys_[i].time));
  FirstPersonCamera pose;
  pose.position = catmull_rom(p0.position, p1.position, p2.position, p3.position, u);
  pose.yaw_degrees = catmull_rom(p0.yaw_degrees, p1.yaw_degrees, p2.yaw_degrees, p3.yaw_degrees, u);
  pose.pitch_degrees = std::clamp(
      catmull_rom(p0.pitch_degrees, p1.pitch_degrees, p2.pitch_degrees, p3.pitch_degrees, u),
      -89.0f, 89.0f);
  return pose;
}

}  // namespace facet::cli
