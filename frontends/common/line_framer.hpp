// Bytes -> text lines, for the text front-ends (imutxt, rtklib). Lines end at '\n' (a '\r'
// before it is dropped); a last line without a newline is still a line at finish(), because
// text tools often omit the final newline. A line longer than the limit, or holding bytes no text
// file has (NUL, other control characters except tab; bytes >= 0x80 are allowed for UTF-8
// comments), is a bad frame: its bytes are skipped up to the next newline and counted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends {

class LineFramer {
 public:
  explicit LineFramer(std::size_t max_line_bytes) : max_line_bytes_(max_line_bytes) {}

  // Calls on_line(std::string_view line) for every complete, clean line (without its end of
  // line). The decoder decides whether a line is a frame, an unknown (comment) line or a bad one
  // and counts it; the framer counts bytes, and bad frames for overlong / binary lines.
  template <typename OnLine>
  void feed(std::span<const std::uint8_t> bytes, OnLine&& on_line) {
    counters_.bytes += bytes.size();
    for (const std::uint8_t b : bytes) {
      ++raw_bytes_;
      ++position_;
      if (b == '\n') {
        end_line(on_line);
        continue;
      }
      if (dirty_) continue;
      const bool text = (b >= 0x20 && b != 0x7f) || b == '\t' || b == '\r';
      if (!text || line_.size() >= max_line_bytes_) {
        dirty_ = true;
        continue;
      }
      line_.push_back(static_cast<char>(b));
    }
  }

  template <typename OnLine>
  void finish(OnLine&& on_line) {
    if (raw_bytes_ > 0) end_line(on_line);
  }

  // A line the decoder found damaged: its bytes are skipped and it counts as one bad frame.
  void reject_line() {
    ++counters_.bad_frames;
    counters_.skipped_bytes += line_raw_bytes_;
  }
  // A line the decoder recognised as not data (comment, header): counted as an unknown frame.
  // Blank lines are not frames at all: their bytes are skipped.
  void skip_line(bool blank) {
    if (!blank) ++counters_.unknown_frames;
    counters_.skipped_bytes += line_raw_bytes_;
  }
  // A line decoded as data.
  void accept_line() { ++counters_.frames; }
  // Byte offset in the stream of the first byte of the line last handed to on_line.
  std::uint64_t line_offset() const { return line_offset_; }

  StreamCounters& counters() { return counters_; }
  const StreamCounters& counters() const { return counters_; }

 private:
  template <typename OnLine>
  void end_line(OnLine& on_line) {
    line_raw_bytes_ = raw_bytes_;
    line_offset_ = position_ - raw_bytes_;
    raw_bytes_ = 0;
    if (dirty_) {
      reject_line();
    } else {
      std::string_view line(line_);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      on_line(line);
    }
    line_.clear();
    dirty_ = false;
  }

  std::size_t max_line_bytes_;
  std::string line_;
  bool dirty_ = false;
  std::uint64_t raw_bytes_ = 0;       // bytes of the line being read, end of line included
  std::uint64_t line_raw_bytes_ = 0;  // the same for the line handed to on_line
  std::uint64_t position_ = 0;        // bytes seen so far
  std::uint64_t line_offset_ = 0;
  StreamCounters counters_;
};

}  // namespace navfuse::frontends
