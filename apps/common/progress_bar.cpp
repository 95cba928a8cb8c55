#include "apps/common/progress_bar.hpp"

#include <unistd.h>

namespace navfuse::apps {
namespace {
constexpr int kWidth = 40;
}  // namespace

ProgressBar::ProgressBar(std::uint64_t total_bytes, bool enabled)
    : total_(total_bytes), active_(enabled && total_bytes >= kMinBytes && ::isatty(STDERR_FILENO) == 1) {}

void ProgressBar::update(std::uint64_t bytes_done) {
  if (!active_) return;
  const int percent = static_cast<int>(bytes_done >= total_ ? 100 : bytes_done * 100 / total_);
  if (percent == shown_percent_) return;
  shown_percent_ = percent;
  char bar[kWidth + 1];
  const int filled = percent * kWidth / 100;
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = '\0';
  std::fprintf(stderr, "\rreplay [%s] %3d%% of %.1f MB", bar, percent, static_cast<double>(total_) / 1e6);
  std::fflush(stderr);
}

void ProgressBar::clear() {
  if (!active_ || shown_percent_ < 0) return;
  std::fprintf(stderr, "\r%*s\r", kWidth + 40, "");
  std::fflush(stderr);
  shown_percent_ = -1;
}

ProgressLines::ProgressLines(std::uint64_t total_bytes, const char* label)
    : total_(total_bytes),
      label_(label),
      enabled_(label != nullptr && total_bytes >= ProgressBar::kMinBytes && ::isatty(STDERR_FILENO) == 0) {}

void ProgressLines::update(std::uint64_t bytes_done) {
  if (!enabled_) return;
  const int tenth = static_cast<int>(10 * bytes_done / total_);
  if (tenth <= shown_) return;
  shown_ = tenth;
  std::fprintf(stderr, "%s: %d %% of %.0f MB processed\n", label_, 10 * tenth, static_cast<double>(total_) / 1e6);
}

}  // namespace navfuse::apps
