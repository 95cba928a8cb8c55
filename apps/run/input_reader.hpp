// One --in stream of the nav process: a thread that reads bytes from the transport, decodes them
// with the stream's front-end and queues the measurements for the filter thread, stamped with
// their arrival time.
//
//  - The transport is opened in the constructor, so a missing file or device, or a port that
//    cannot be bound, is reported before anything starts (a one-line CommandError).
//  - Links that drop (a device unplugged, a TCP peer gone) are re-opened by the transport itself;
//    the reader logs the loss and the recovery and, with --configure-device, sets the device up
//    again.
//  - With --configure-device a refused set-up command, or a setting that does not read back as
//    written, ends the input (setup_failed()): the nav process then stops with that error.
//  - Without a FORMAT: prefix the format is detected from the first bytes received.
//  - A live input never waits for the filter: when the queue is full the measurement is dropped
//    and counted. A file input is not live, so it waits for room instead of losing data, and
//    with --realtime it is also paced by its own timestamps (realtime_pacer.hpp).
//  - Each read is decoded first, then its measurements are queued as one block; with --record the
//    read is written, numbered, under the recorder's lock that keeps that order (input_recorder.hpp).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "apps/run/arrived_measurement.hpp"
#include "apps/run/input_endpoint.hpp"
#include "apps/run/input_recorder.hpp"
#include "apps/run/realtime_pacer.hpp"
#include "core/config/config.hpp"
#include "core/io/transport.hpp"

namespace navfuse::apps {

// A consistent-enough snapshot for status reporting (each counter is read atomically).
struct InputCounters {
  std::uint64_t bytes = 0;
  std::uint64_t frames = 0;
  std::uint64_t bad_frames = 0;
  std::uint64_t measurements = 0;  // queued for the filter
  std::uint64_t dropped = 0;       // lost because the filter queue was full
  std::uint64_t reconnects = 0;
  bool ended = false;              // end of stream (files) or a fatal error
};

class InputReader {
 public:
  // Opens the transport; throws CommandError naming the input when that fails.
  // `device_config` (--configure-device; null: the device is not set up) gives the installation
  // geometry sent to the device; it must outlive the reader.
  // `recorder` (may be null) writes this input's raw bytes; `pacer` (may be null) paces a file input.
  InputReader(InputEndpoint endpoint, std::uint16_t index, MeasurementQueue& queue, const config::Config* device_config,
              std::unique_ptr<StreamRecorder> recorder, RealtimePacer* pacer);
  ~InputReader();
  InputReader(const InputReader&) = delete;
  InputReader& operator=(const InputReader&) = delete;

  void start();
  void request_stop() { stop_.store(true, std::memory_order_relaxed); }
  void join();

  const std::string& name() const { return endpoint_.text; }
  // The front-end in use ("" until detected).
  std::string_view format() const;
  InputCounters counters() const;
  // From another thread: bytes for the device (RTK corrections), written by this reader's thread
  // between reads. Returns the bytes accepted: 0 when kMaxOutgoingBytes are already waiting.
  std::size_t send(std::span<const std::uint8_t> bytes);
  static constexpr std::size_t kMaxOutgoingBytes = 65536;
  bool ended() const { return ended_.load(std::memory_order_acquire); }
  // The device refused its set-up or a setting did not read back as written (then the input has
  // stopped); setup_error() says which, with the values sent and read.
  bool setup_failed() const { return setup_failed_.load(std::memory_order_acquire); }
  std::string setup_error() const;

 private:
  class QueueSink;

  void run();
  void configure_device();
  void fail_setup(const std::string& why);
  // Collects the head of a stream without a format prefix; creates the decoder once detected.
  void detect(std::span<const std::uint8_t> bytes, bool at_end);
  void use_frontend(const frontends::FrontendInfo* frontend);
  // One read: decoded, paced (file inputs with --realtime), recorded, queued.
  void ingest(std::span<const std::uint8_t> bytes);
  void decode(std::span<const std::uint8_t> bytes);
  void finish_stream();
  void watch_link();  // logs losses and recoveries, re-configures a replugged device
  void publish_counters();
  void write_outgoing();

  InputEndpoint endpoint_;
  std::uint16_t index_;
  MeasurementQueue& queue_;
  const config::Config* device_config_;  // --configure-device, else null
  bool live_;  // not a regular file: never wait for the filter
  std::unique_ptr<io::Transport> transport_;
  std::unique_ptr<frontends::StreamDecoder> decoder_;
  std::unique_ptr<QueueSink> sink_;
  std::unique_ptr<StreamRecorder> recorder_;
  RealtimePacer* pacer_;
  std::optional<std::uint64_t> decode_started_from_;  // detection succeeded in the current read
  std::atomic<const frontends::FrontendInfo*> frontend_{nullptr};
  std::vector<std::uint8_t> head_;  // bytes kept for format detection
  bool detection_failed_logged_ = false;
  std::uint64_t seen_reconnects_ = 0;
  std::uint64_t seen_errors_ = 0;

  std::mutex outgoing_mutex_;
  std::vector<std::uint8_t> outgoing_;       // under outgoing_mutex_
  std::vector<std::uint8_t> writing_;        // reader thread only
  bool outgoing_failure_logged_ = false;

  mutable std::mutex setup_error_mutex_;
  std::string setup_error_;  // under setup_error_mutex_
  std::atomic<bool> setup_failed_{false};

  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> ended_{false};
  std::atomic<std::uint64_t> bytes_{0}, frames_{0}, bad_frames_{0}, measurements_{0}, dropped_{0},
      reconnects_{0};
};

}  // namespace navfuse::apps
