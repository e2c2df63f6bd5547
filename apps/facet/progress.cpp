// Progress of a frame sequence (see progress.hpp).
#include "progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace facet::cli {
namespace {

constexpr double kRedrawSeconds = 0.1;  // the bar is redrawn at most this often
constexpr const char* kBarText = " %d/%d %s  %.1f %s/s  %s left";

int terminal_columns(std::FILE* out) {
  winsize size{};
  if (::ioctl(::fileno(out), TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

// "0:07", "12:30", "1:02:03".
std::string clock_time(double seconds) {
  long total = std::lround(std::max(seconds, 0.0));
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

}  // namespace

Progress::Style Progress::style_for(std::FILE* out, bool quiet) {
  if (quiet) return Style::quiet;
  return ::isatty(::fileno(out)) ? Style::bar : Style::lines;
}

Progress::Progress(Style style, int total, std::FILE* out, const char* unit)
    : style_(style), total_(total), out_(out), unit_(unit) {
  if (style_ != Style::bar) return;
  // The bar keeps one width, made to leave room for the longest text beside it.
  char longest[160];
  std::snprintf(longest, sizeof longest, kBarText, total, total, unit_, 99999.9, unit_, "99:59:59");
  bar_width_ =
      std::clamp(terminal_columns(out_) - static_cast<int>(std::strlen(longest)) - 3, 10, 40);
}

double Progress::seconds() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void Progress::start(const std::string& text) {
  if (style_ == Style::quiet) return;
  std::fprintf(out_, "%s\n", text.c_str());
  draw_bar(true);
  std::fflush(out_);
}

void Progress::skipped(int frame) {
  ++skipped_;
  if (style_ == Style::lines) {
    std::fprintf(out_, "frame %d (%d/%d): skipped, already written\n", frame, done(), total_);
    std::fflush(out_);
  }
  draw_bar(done() == total_);
}

void Progress::failed() {
  ++failed_;
  draw_bar(done() == total_);
}

void Progress::rendered(int frame, const std::vector<std::string>& files, double render_ms,
                        double write_ms) {
  ++rendered_;
  if (style_ == Style::lines) {
    std::string names;
    for (const std::string& file : files) names += (names.empty() ? "" : ", ") + file;
    std::fprintf(out_, "frame %d (%d/%d): %s; render %.1f ms, write %.1f ms\n", frame, done(),
                 total_, names.c_str(), render_ms, write_ms);
    std::fflush(out_);
  }
  draw_bar(done() == total_);
}

void Progress::draw_bar(bool force) {
  if (style_ != Style::bar) return;
  double now = seconds();
  if (!force && drawn_at_ >= 0.0 && now - drawn_at_ < kRedrawSeconds) return;
  if (force && drawn_done_ == done() && done() == total_) return;  // the end, drawn already
  drawn_at_ = now;
  drawn_done_ = done();
  // Frames skipped as already written took no time: the rate counts the rendered ones only.
  double rate = now > 0.0 ? rendered_ / now : 0.0;
  std::string left = rendered_ > 0 && rate > 0.0 ? clock_time((total_ - done()) / rate) : "-:--";
  char text[160];
  std::snprintf(text, sizeof text, kBarText, done(), total_, unit_, rate, unit_, left.c_str());
  int filled =
      total_ > 0 ? static_cast<int>(static_cast<long long>(bar_width_) * done() / total_) : 0;
  std::string bar(bar_width_ + 2, '.');
  bar.front() = '[', bar.back() = ']';
  std::fill_n(bar.begin() + 1, filled, '#');
  // \r back to the line's start, \033[K clears what a longer previous line left.
  std::fprintf(out_, "\r%s%s\033[K", bar.c_str(), text);
  std::fflush(out_);
  line_open_ = true;
}

void Progress::end_line() {
  if (!line_open_) return;
  std::fputc('\n', out_);
  std::fflush(out_);
  line_open_ = false;
}

void Progress::finish() {
  draw_bar(true);
  end_line();
  if (style_ == Style::quiet) return;
  double elapsed = seconds();
  std::fprintf(out_,
               "%d frames in %.1f s (%.1f frames/s): %d rendered, %d skipped as already "
               "written\n",
               done(), elapsed, elapsed > 0.0 ? rendered_ / elapsed : 0.0, rendered_, skipped_);
  std::fflush(out_);
}

}  // namespace facet::cli
