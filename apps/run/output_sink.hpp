// One output link of the nav process (--fe-out, --mip-out): a thread that owns the transport and
// the device emulator speaking on it. It streams what the emulator encodes from the epochs the
// filter thread posts, and answers the commands clients send back on the same link (a
// tcp-listen:// output is also the device's command port, as on a real receiver).
//
// Never blocking the filter: post() only copies into a bounded queue and drops (counted) when the
// link's thread falls behind; the transports themselves never wait on a slow client (core/io
// cuts off a tcp-listen client whose backlog overflows, counted as clients_dropped).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "apps/run/arrived_measurement.hpp"
#include "apps/run/device_emulator.hpp"
#include "apps/run/engine_action.hpp"
#include "apps/fusion/output_epoch.hpp"
#include "core/io/transport.hpp"
#include "core/io/uri.hpp"

namespace navfuse::apps {

class OutputSink {
 public:
  // Opens the transport now (throws CommandError naming `option` and the URI when it cannot).
  // Aiding received in commands goes to `aiding_queue`, engine requests to `actions`.
  OutputSink(std::string option, const io::Uri& uri, std::unique_ptr<DeviceEmulator> device,
             MeasurementQueue& aiding_queue, EngineActionQueue& actions);
  ~OutputSink();
  OutputSink(const OutputSink&) = delete;
  OutputSink& operator=(const OutputSink&) = delete;

  void start();
  // Streams what is still queued, gives the transport a bounded moment to flush, then stops.
  void stop();

  // From the filter thread: never waits; false when the epoch was dropped.
  bool post(const OutputEpoch& epoch);

  // Epochs dropped because this thread fell behind, plus clients cut off for falling behind.
  std::uint64_t drops() const;
  const std::string& name() const { return name_; }
  // After stop(): for a file output (file:PATH), the first write error ("--fe-out file:/x: write:
  // No space left on device (1234 bytes lost)"), else "". A file that lost bytes is a failed run
  // (issue 15.7); a network client that went away is not.
  std::string write_error() const;

 private:
  void run();
  void stream(const OutputEpoch& epoch);
  void serve_commands();
  void flush_transport();

  std::string option_;  // "--fe-out"
  std::string name_;    // "--fe-out tcp-listen://:7000", for messages
  bool duplex_;       // commands can come back (not a file)
  std::unique_ptr<io::Transport> transport_;
  std::unique_ptr<DeviceEmulator> device_;
  MeasurementQueue& aiding_queue_;
  EngineActionQueue& actions_;
  BoundedQueue<OutputEpoch> queue_;

  // Output thread only, reused to avoid allocating per epoch.
  OutputEpoch current_;
  std::vector<std::uint8_t> bytes_;
  std::vector<std::uint8_t> read_buffer_;
  std::vector<std::uint8_t> reply_;
  CommandEffects effects_;
  ArrivedMeasurement aiding_item_;

  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> queue_drops_{0};
  std::atomic<std::uint64_t> clients_dropped_{0};
  std::uint64_t errors_logged_ = 0;  // output thread: transport errors already logged
  std::string first_write_error_;    // output thread until stop()
};

}  // namespace navfuse::apps
