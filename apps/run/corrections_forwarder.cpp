#include "apps/run/corrections_forwarder.hpp"

#include <array>
#include <chrono>

#include "apps/common/command_error.hpp"
#include "apps/run/arrived_measurement.hpp"
#include "apps/run/run_log.hpp"

namespace navfuse::apps {
namespace {

constexpr int kReadTimeoutMs = 100;  // how often the thread looks at the stop flag
constexpr std::size_t kReadChunk = 4096;

}  // namespace

CorrectionsForwarder::CorrectionsForwarder(CorrectionsSource source, InputReader& receiver,
                                           const RoverPosition* position)
    : source_(std::move(source)), receiver_(receiver), position_(position) {
  try {
    transport_ = io::open_transport("tcp://" + source_.host + ":" + std::to_string(source_.port), io::Direction::kBoth);
  } catch (const io::TransportError& e) {
    throw CommandError("--corrections '" + source_.text + "': " + e.what());
  }
}

CorrectionsForwarder::~CorrectionsForwarder() { stop(); }

void CorrectionsForwarder::start() { thread_ = std::thread([this] { run(); }); }

void CorrectionsForwarder::stop() {
  stop_.store(true, std::memory_order_relaxed);
  if (thread_.joinable()) thread_.join();
}

nlohmann::ordered_json CorrectionsForwarder::counters() const {
  constexpr auto r = std::memory_order_relaxed;
  return {{"source", source_.text},          {"to", receiver_.name()},
          {"connections", connections_.load(r)}, {"refusals", refusals_.load(r)},
          {"bytes_received", bytes_in_.load(r)}, {"bytes_forwarded", bytes_forwarded_.load(r)},
          {"gga_sent", gga_sent_.load(r)}};
}

void CorrectionsForwarder::run() {
  std::array<std::uint8_t, kReadChunk> buffer{};
  std::uint64_t seen_reconnects = transport_->stats().reconnects;
  while (!stop_.load(std::memory_order_relaxed)) {
    const std::ptrdiff_t n = transport_->read(buffer, kReadTimeoutMs);
    // A new connection (the first, or the transport's reconnect after a loss) starts over.
    const std::uint64_t reconnects = transport_->stats().reconnects;
    if (transport_->is_open() && (!connected_ || reconnects != seen_reconnects)) {
      seen_reconnects = reconnects;
      on_connected();
    } else if (!transport_->is_open() && connected_) {
      connected_ = false;
      log_event("corrections '" + source_.text + "' lost: " + transport_->stats().last_error + "; reconnecting");
    }
    if (n > 0) on_bytes(std::span<const std::uint8_t>(buffer.data(), static_cast<std::size_t>(n)));
    if (connected_) upload_gga_when_due();
  }
}

void CorrectionsForwarder::on_connected() {
  connected_ = true;
  connections_.fetch_add(1, std::memory_order_relaxed);
  streaming_ = !source_.ntrip;
  head_.clear();
  chunks_ = ChunkedDecoder();
  chunked_ = false;
  next_gga_ns_ = 0;  // a new connection is a new client to the caster: tell it at once
  if (source_.ntrip) {
    const bool gga = take_gga();
    const std::string request =
        ntrip_request(source_, gga ? std::string_view(reinterpret_cast<const char*>(gga_.data()), gga_.size())
                                   : std::string_view{});
    const auto sent = transport_->write(std::span(reinterpret_cast<const std::uint8_t*>(request.data()), request.size()));
    if (gga && sent > 0) gga_uploaded();
  }
  log_event("corrections '" + source_.text + "' connected; forwarding to '" + receiver_.name() + "'");
}

void CorrectionsForwarder::on_bytes(std::span<const std::uint8_t> bytes) {
  bytes_in_.fetch_add(bytes.size(), std::memory_order_relaxed);
  if (!streaming_) {
    head_.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const std::optional<NtripAnswer> answer = parse_ntrip_answer(head_, source_.mount);
    if (!answer) return;
    if (!answer->ok) return refused(answer->reason);
    streaming_ = true;
    chunked_ = answer->chunked;
    const std::string rest = head_.substr(answer->header_bytes);
    head_.clear();
    return forward(std::span(reinterpret_cast<const std::uint8_t*>(rest.data()), rest.size()));
  }
  forward(bytes);
}

void CorrectionsForwarder::forward(std::span<const std::uint8_t> bytes) {
  data_.clear();
  if (chunked_) {
    if (!chunks_.feed(bytes, data_)) return refused("malformed NTRIP 2.0 chunk");
  } else {
    data_.assign(bytes.begin(), bytes.end());
  }
  if (!data_.empty()) bytes_forwarded_.fetch_add(receiver_.send(data_), std::memory_order_relaxed);
}

bool CorrectionsForwarder::take_gga() {
  if (position_ == nullptr || !(source_.gga_interval_s > 0.0)) return false;
  gga_.clear();
  return position_->append_gga(gga_);
}

void CorrectionsForwarder::upload_gga_when_due() {
  if (monotonic_ns() < next_gga_ns_ || !take_gga()) return;
  // A write the transport refuses (link just lost) is tried again at the next wake, not counted.
  if (transport_->write(gga_) > 0) gga_uploaded();
}

void CorrectionsForwarder::gga_uploaded() {
  gga_sent_.fetch_add(1, std::memory_order_relaxed);
  next_gga_ns_ = monotonic_ns() + static_cast<std::int64_t>(source_.gga_interval_s * 1e9);
}

void CorrectionsForwarder::refused(const std::string& reason) {
  refusals_.fetch_add(1, std::memory_order_relaxed);
  log_event("corrections '" + source_.text + "': " + reason + "; asking again in " +
            std::to_string(static_cast<int>(kRetryS)) + " s");
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(kRetryS);
  while (std::chrono::steady_clock::now() < until && !stop_.load(std::memory_order_relaxed)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(kReadTimeoutMs));
  }
  transport_->reopen();
  connected_ = false;
}

}  // namespace navfuse::apps
