// `navfuse run --corrections SOURCE --corrections-to N`: RTK corrections (RTCM) from an NTRIP
// caster or a raw TCP source, written unchanged to input N's port, the receiver's, as an NTRIP
// client such as the receiver's own would. One thread: it connects (and reconnects, the
// transport's backoff), asks an NTRIP caster for the mountpoint, undoes NTRIP 2.0's chunking,
// and hands the bytes to the input's reader, which writes them between its reads (its transport
// is its own thread's). A refusal by the caster (no such mountpoint, wrong password) is logged
// once per connection with its reason, and asked again after kRetryS.
//
// With gga=SECONDS in the source, the rover's position goes upstream as an NMEA GGA sentence
// (apps/run/rover_position.hpp) on connecting (in the request, ntrip_request) and then every
// SECONDS on the same connection, as network-RTK (VRS) casters require. Until the filter has a
// position nothing is sent, and the first one goes out as soon as there is one.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/run/input_reader.hpp"
#include "apps/run/ntrip_protocol.hpp"
#include "apps/run/rover_position.hpp"
#include "core/io/transport.hpp"

namespace navfuse::apps {

class CorrectionsForwarder {
 public:
  static constexpr double kRetryS = 2.0;

  // Opens the connection (throws CommandError for a host that does not resolve). `position`, read
  // for the GGA uploads, is needed when source.gga_interval_s > 0 and must outlive the forwarder.
  CorrectionsForwarder(CorrectionsSource source, InputReader& receiver, const RoverPosition* position);
  ~CorrectionsForwarder();
  CorrectionsForwarder(const CorrectionsForwarder&) = delete;
  CorrectionsForwarder& operator=(const CorrectionsForwarder&) = delete;

  void start();
  void stop();
  // For the run summary: source, bytes received and handed on, connections, refusals, GGA
  // sentences sent.
  nlohmann::ordered_json counters() const;

 private:
  void run();
  void on_connected();
  void on_bytes(std::span<const std::uint8_t> bytes);
  void forward(std::span<const std::uint8_t> bytes);  // the data after the caster's answer
  void refused(const std::string& reason);
  // The rover's GGA sentence into gga_ when the source asks for uploads and a position is known.
  bool take_gga();
  void upload_gga_when_due();
  void gga_uploaded();  // counts it and schedules the next

  CorrectionsSource source_;
  InputReader& receiver_;
  const RoverPosition* position_;
  std::unique_ptr<io::Transport> transport_;
  // Thread state.
  bool connected_ = false;
  bool streaming_ = false;  // past the caster's answer
  std::string head_;        // the caster's answer so far
  ChunkedDecoder chunks_;
  bool chunked_ = false;
  std::vector<std::uint8_t> data_;
  std::vector<std::uint8_t> gga_;
  std::int64_t next_gga_ns_ = 0;  // steady clock; 0: as soon as a position is known

  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> bytes_in_{0}, bytes_forwarded_{0}, connections_{0}, refusals_{0}, gga_sent_{0};
};

}  // namespace navfuse::apps
