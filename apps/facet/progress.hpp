// How `facet render --frames` reports on standard output: on a terminal one line redrawn in
// place (a bar, frames done of the total, frames per second, time left); otherwise one plain
// line per frame, for logs and schedulers; nothing with --quiet. Errors go to standard error
// whatever the style. A batch of models (render_batch.hpp) uses the bar alone, counting models.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace facet::cli {

class Progress {
 public:
  enum class Style { bar, lines, quiet };
  // bar if `out` is a terminal, else lines; quiet if asked.
  static Style style_for(std::FILE* out, bool quiet);

  // `unit` names what is counted in the bar ("frames", or "models" for a batch).
  Progress(Style style, int total, std::FILE* out = stdout, const char* unit = "frames");

  // One line before the first frame (not shown in quiet style).
  void start(const std::string& text);
  void skipped(int frame);
  // A batch's model that could not be drawn (its error is printed by the caller): done, not
  // rendered.
  void failed();
  void rendered(int frame, const std::vector<std::string>& files, double render_ms,
                double write_ms);
  // Ends the bar's line, so that what is printed next starts on its own (before an error).
  void end_line();
  // The last line: frames rendered and skipped, the time taken and the rate.
  void finish();

  int done() const { return rendered_ + skipped_ + failed_; }

 private:
  using Clock = std::chrono::steady_clock;
  void draw_bar(bool force);
  double seconds() const;

  Style style_;
  int total_;
  std::FILE* out_;
  const char* unit_;
  int rendered_ = 0;
  int skipped_ = 0;
  int failed_ = 0;
  Clock::time_point start_ = Clock::now();
  int bar_width_ = 0;       // characters between the brackets
  double drawn_at_ = -1.0;  // seconds when the bar was last drawn
  int drawn_done_ = -1;     // frames done when it was
  bool line_open_ = false;  // the bar's line has no newline yet
};

}  // namespace facet::cli
