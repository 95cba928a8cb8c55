// Several logs read as one stream ordered by measurement time (DESIGN.md: "several inputs are
// merged by measurement time", e.g. a VN-300 log plus a FusionEngine wheel-speed log).
//
// Each input is decoded a chunk at a time into its own small queue; a priority queue holds the
// head measurement of every input with data, keyed by (time_ns, input index), so memory is
// bounded by one chunk's measurements per input whatever the log lengths. This is a k-way merge:
// it assumes each input is roughly in time order (what a device port delivers). Measurements a
// device delivers late stay late within their stream; the filter fuses those from its history.
//
// A recording of `navfuse run --record` (recording_format.hpp) is merged in the live run's order
// instead: the reads of all inputs in their recorded sequence, each decoded as the live run
// decoded it (format detection's start included), so the filter sees what it saw live.
//
// Every measurement's header.stream_id is set to its input's index.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "apps/common/input_spec.hpp"
#include "apps/common/recording_format.hpp"
#include "apps/common/summary.hpp"
#include "core/measurements/measurements.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::apps {

class MeasurementMerger {
 public:
  struct Options {
    std::size_t chunk_bytes = 16 * 1024;
    // A trailing incomplete frame (a cut-off log) is an error unless allowed.
    bool allow_truncated = false;
  };

  // Opens every input; throws CommandError naming the file when one cannot be opened.
  MeasurementMerger(const std::vector<InputSpec>& inputs, const Options& options);
  // The inputs of a recording, in recorded order. A recording cut off mid-frame (the run was
  // stopped) is normal: such inputs are listed in truncated_inputs(), not an error.
  MeasurementMerger(const Recording& recording, const Options& options);
  ~MeasurementMerger();
  MeasurementMerger(const MeasurementMerger&) = delete;
  MeasurementMerger& operator=(const MeasurementMerger&) = delete;

  // Next measurement in merged time order, valid until the next call (it stays in its input's
  // queue: no copy); nullptr once every input is exhausted. Throws CommandError on a read error
  // or (unless allowed) a truncated input.
  const Measurement* next();

  // Per input: path, format and the decoder's counters (final after next() returned false).
  std::vector<InputSummary> input_summaries() const;
  // Measurements decoded so far, per kind.
  const std::array<std::uint64_t, static_cast<std::size_t>(MeasurementKind::kCount)>& decoded() const {
    return decoded_;
  }
  std::uint64_t bytes_read() const { return bytes_read_; }
  std::uint64_t total_bytes() const { return total_bytes_; }
  // Inputs whose last frame was cut off (only when allow_truncated).
  const std::vector<std::string>& truncated_inputs() const { return truncated_; }

 private:
  struct Stream;
  struct Head {
    std::int64_t key;  // measurement time, or for a recording the read's sequence number
    std::size_t input;
    bool operator>(const Head& o) const { return key != o.key ? key > o.key : input > o.input; }
  };
  void start();
  // Decodes chunks of input `i` until it has a queued measurement or ends.
  void refill(std::size_t i);
  void refill_recorded(Stream& s);
  void end_of_input(Stream& s);
  void push_head(std::size_t i);

  Options options_;
  std::vector<std::unique_ptr<Stream>> streams_;
  std::priority_queue<Head, std::vector<Head>, std::greater<Head>> heads_;
  std::vector<std::uint8_t> chunk_;
  std::array<std::uint64_t, static_cast<std::size_t>(MeasurementKind::kCount)> decoded_{};
  std::uint64_t bytes_read_ = 0;
  std::uint64_t total_bytes_ = 0;
  std::vector<std::string> truncated_;
  // The input the last next() took from: refilled (and its head queued) by the following call,
  // once the measurement it returned is done with.
  std::optional<std::size_t> taken_from_;
};

}  // namespace navfuse::apps
