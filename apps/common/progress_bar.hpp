// A one-line progress bar on stderr for long replays: shown only when stderr is a terminal (so
// logs and pipes never get carriage returns) and the input is large enough to take a while.
// Redrawn only when the whole percentage changes, so it costs nothing measurable per sample.
#pragma once

#include <cstdint>
#include <cstdio>

namespace navfuse::apps {

class ProgressBar {
 public:
  // Inputs smaller than this replay in well under a second: no bar.
  static constexpr std::uint64_t kMinBytes = 16ull << 20;

  ProgressBar(std::uint64_t total_bytes, bool enabled);
  ~ProgressBar() { clear(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void update(std::uint64_t bytes_done);
  // Erases the bar (before the summary is printed).
  void clear();

 private:
  std::uint64_t total_;
  bool active_;
  int shown_percent_ = -1;
};

// Progress of a long run when stderr is not a terminal (CI logs, pipes): a line every 10 %,
// where a terminal gets the redrawn bar instead. `label` (e.g. "navfuse bench") starts each
// line; nullptr disables it.
class ProgressLines {
 public:
  ProgressLines(std::uint64_t total_bytes, const char* label);
  void update(std::uint64_t bytes_done);

 private:
  std::uint64_t total_;
  const char* label_;
  bool enabled_;
  int shown_ = 0;
};

}  // namespace navfuse::apps
