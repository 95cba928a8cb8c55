// `navfuse run --corrections SOURCE --corrections-to N`: RTK corrections (RTCM) from an NTRIP
// caster or a raw TCP source, written unchanged to input N's port, the receiver's, as an NTRIP
// client such as the receiver's own would. One thread: it connects (and reconnects, the
// transport's backoff), asks an NTRIP caster for the mountpoint, undoes NTRIP 2.0's chunking,
// and hands the bytes to the input's reader, which writes them between its reads (its transport
// is its own thread's). A refusal by the caster (no such mountpoint, wrong password) is logged
// once per connection with its reason, and asked again after kRetryS.
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
#include "core/io/transport.hpp"

namespace navfuse::apps {

class CorrectionsForwarder {
 public:
  static constexpr double kRetryS = 2.0;

  // Opens the connection (throws CommandError for a host that does not resolve).
  CorrectionsForwarder(CorrectionsSource source, InputReader& receiver);
  ~CorrectionsForwarder();
  CorrectionsForwarder(const CorrectionsForwarder&) = delete;
  CorrectionsForwarder& operator=(const CorrectionsForwarder&) = delete;

  void start();
  void stop();
  // For the run summary: source, bytes received and handed on, connections, refusals.
  nlohmann::ordered_json counters() const;

 private:
  void run();
  void on_connected();
  void on_bytes(std::span<const std::uint8_t> bytes);
  void forward(std::span<const std::uint8_t> bytes);  // the data after the caster's answer
  void refused(const std::string& reason);

  CorrectionsSource source_;
  InputReader& receiver_;
  std::unique_ptr<io::Transport> transport_;
  // Thread state.
  bool connected_ = false;
  bool streaming_ = false;  // past the caster's answer
  std::string head_;        // the caster's answer so far
  ChunkedDecoder chunks_;
  bool chunked_ = false;
  std::vector<std::uint8_t> data_;

  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> bytes_in_{0}, bytes_forwarded_{0}, connections_{0}, refusals_{0};
};

}  // namespace navfuse::apps
