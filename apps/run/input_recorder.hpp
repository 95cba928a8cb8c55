// `navfuse run --record DIR`: every input's raw bytes with their host receive times, written as
// apps/common/recording_format.hpp describes, so that `navfuse replay --recording DIR` gives the
// filter the live run's exact sequence of measurements.
//
// Exactness needs the order in which the reads' measurements reached the filter queue. Each
// input decodes a read on its own thread, then, holding the recorder's lock, numbers the read,
// writes it and queues its measurements: the queue then holds whole reads in number order.
// (Measurements dropped because the queue was full, aiding from LCM and commands on the output
// links are not inputs and are not recorded: a run with any of them replays without them.)
//
// A write failure (disk full) is reported once and ends that input's recording; the run goes on.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace navfuse::apps {

class StreamRecorder;

class RunRecorder {
 public:
  // Creates DIR (refusing one that already holds a recording), copies the config and writes the
  // manifest. Throws CommandError naming the path on failure.
  RunRecorder(const std::string& dir, const std::string& config_path, const std::vector<std::string>& arguments);
  // The recorder of input `index` (its files are opened now).
  std::unique_ptr<StreamRecorder> open_stream(std::size_t index, const std::string& name);

 private:
  friend class StreamRecorder;
  std::string dir_;
  std::mutex order_;
  std::int64_t next_seq_ = 0;  // under order_
};

class StreamRecorder {
 public:
  StreamRecorder(RunRecorder& recorder, const std::string& raw_path, const std::string& index_path, std::string name);
  ~StreamRecorder();
  StreamRecorder(const StreamRecorder&) = delete;
  StreamRecorder& operator=(const StreamRecorder&) = delete;

  // Numbers and writes one read. The returned lock keeps the recorder's order: queue the read's
  // measurements before releasing it.
  [[nodiscard]] std::unique_lock<std::mutex> read(std::span<const std::uint8_t> bytes, std::int64_t mono_ns);
  // Decoding started as `format` from byte `from_offset`: after the last read() (under its lock),
  // or before any read when the format was given.
  void decoding(std::string_view format, std::uint64_t from_offset);
  // The input ended; queue what its decoder flushed before releasing the lock.
  [[nodiscard]] std::unique_lock<std::mutex> end(std::int64_t mono_ns);

 private:
  void check(bool ok);
  void flush_every_second(std::int64_t mono_ns);

  RunRecorder& recorder_;
  std::string name_;
  std::FILE* raw_ = nullptr;
  std::FILE* index_ = nullptr;
  std::int64_t last_seq_ = -1;
  std::int64_t last_flush_ns_ = 0;
  bool failed_ = false;
};

}  // namespace navfuse::apps
