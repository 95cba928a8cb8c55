#include "apps/run/output_sink.hpp"

#include <chrono>

#include "apps/common/command_error.hpp"
#include "apps/run/run_log.hpp"

namespace navfuse::apps {
namespace {

constexpr std::size_t kQueueCapacity = 512;  // > 1 s of epochs at 400 Hz
// How long the thread sleeps waiting for an epoch: the worst-case delay in answering a command
// while the filter is idle (no input).
constexpr auto kIdleWait = std::chrono::milliseconds(5);
constexpr std::size_t kReadBuffer = 4096;
constexpr int kCommandReadsPerWake = 16;  // bounded: commands cannot starve the stream
constexpr int kFlushRounds = 10;          // at exit: 10 x 20 ms for queued bytes to leave
constexpr int kFlushWaitMs = 20;

}  // namespace

OutputSink::OutputSink(std::string option, const io::Uri& uri, std::unique_ptr<DeviceEmulator> device,
                       MeasurementQueue& aiding_queue, EngineActionQueue& actions)
    : option_(std::move(option)),
      name_(option_ + " " + uri.text),
      duplex_(uri.scheme != io::Scheme::kFile),
      device_(std::move(device)),
      aiding_queue_(aiding_queue),
      actions_(actions),
      queue_(kQueueCapacity),
      read_buffer_(kReadBuffer) {
  try {
    transport_ = io::open_transport(uri, io::Direction::kOutput);
  } catch (const io::TransportError& e) {
    throw CommandError(name_ + ": " + e.what());
  }
  bytes_.reserve(4096);
  aiding_item_.source = kSourceOutputCommand;
}

OutputSink::~OutputSink() { stop(); }

void OutputSink::start() { thread_ = std::thread([this] { run(); }); }

void OutputSink::stop() {
  if (!thread_.joinable()) return;
  stop_.store(true, std::memory_order_relaxed);
  queue_.close();
  thread_.join();
}

bool OutputSink::post(const OutputEpoch& epoch) {
  if (queue_.try_push(epoch)) return true;
  queue_drops_.fetch_add(1, std::memory_order_relaxed);
  return false;
}

std::uint64_t OutputSink::drops() const {
  return queue_drops_.load(std::memory_order_relaxed) + clients_dropped_.load(std::memory_order_relaxed);
}

void OutputSink::run() {
  while (!stop_.load(std::memory_order_relaxed)) {
    if (queue_.pop_wait(current_, kIdleWait)) {
      stream(current_);
      while (queue_.try_pop(current_)) stream(current_);
    }
    if (duplex_) serve_commands();
  }
  while (queue_.try_pop(current_)) stream(current_);
  flush_transport();
}

void OutputSink::stream(const OutputEpoch& epoch) {
  bytes_.clear();
  device_->stream(epoch, bytes_);
  // A write that no client takes (none connected yet) is not a drop: nobody is behind.
  if (!bytes_.empty()) transport_->write(bytes_);
  const io::TransportStats& stats = transport_->stats();
  clients_dropped_.store(stats.clients_dropped, std::memory_order_relaxed);
  if (!duplex_ && stats.errors > errors_logged_) {
    // Logged once as it happens (a full disk fails every write after the first).
    if (errors_logged_ == 0) {
      first_write_error_ = option_ + " " + stats.last_error;  // last_error names the URI
      log_event(first_write_error_);
    }
    errors_logged_ = stats.errors;
  }
}

std::string OutputSink::write_error() const {
  if (first_write_error_.empty()) return "";
  return first_write_error_ + " (" + std::to_string(transport_->stats().bytes_dropped) + " bytes lost)";
}

void OutputSink::serve_commands() {
  for (int i = 0; i < kCommandReadsPerWake; ++i) {
    io::PeerId peer = io::kNoPeer;
    const std::ptrdiff_t n = transport_->read_from(read_buffer_, 0, peer);
    if (n <= 0) return;
    reply_.clear();
    effects_.clear();
    device_->receive(peer, std::span<const std::uint8_t>(read_buffer_.data(), static_cast<std::size_t>(n)),
                     reply_, effects_);
    if (!reply_.empty() && transport_->write_to(peer, reply_) <= 0) {
      log_event(name_ + ": could not send a command reply (client gone or behind)");
    }
    const std::int64_t now = monotonic_ns();
    for (const Measurement& m : effects_.aiding) {
      aiding_item_.measurement = m;
      aiding_item_.arrival_ns = now;
      if (!aiding_queue_.try_push(aiding_item_)) log_event(name_ + ": filter queue full, aiding dropped");
    }
    for (const EngineAction& a : effects_.actions) {
      if (!actions_.try_push(a)) log_event(name_ + ": filter busy, command action dropped");
    }
  }
}

void OutputSink::flush_transport() {
  if (!duplex_) return;  // files are written through; nothing is queued
  // Transports flush their queued bytes while reading (core/io): give them a bounded moment.
  for (int i = 0; i < kFlushRounds; ++i) {
    io::PeerId peer = io::kNoPeer;
    transport_->read_from(read_buffer_, kFlushWaitMs, peer);
  }
}

}  // namespace navfuse::apps
