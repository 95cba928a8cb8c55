#include "apps/run/input_reader.hpp"

#include <sys/stat.h>

#include <array>
#include <chrono>

#include "apps/common/command_error.hpp"
#include "apps/common/frontend_registry.hpp"
#include "apps/run/device_setup.hpp"
#include "apps/run/run_log.hpp"

namespace navfuse::apps {
namespace {

constexpr int kReadTimeoutMs = 100;        // how often a quiet reader looks at the stop flag
constexpr std::size_t kReadChunk = 16384;  // one read; a VN-300 at 921600 baud fills ~92 kB/s
constexpr std::size_t kPacedReadChunk = 64;  // --realtime file reads: about one frame each
// Detection waits for this many bytes so that every probe sees a few whole frames.
constexpr std::size_t kDetectMinBytes = 2048;
// --configure-device: how long to wait for a device's answer to one command, and the quiet
// gap that ends an answer.
constexpr auto kReplyTimeout = std::chrono::milliseconds(250);
constexpr int kReplyQuietMs = 30;

bool is_regular_file(const io::Uri& uri) {
  struct stat st {};
  return uri.scheme == io::Scheme::kFile && uri.path != "-" && ::stat(uri.path.c_str(), &st) == 0 &&
         S_ISREG(st.st_mode);
}

}  // namespace

// Collects a read's decoded measurements, stamped with their input and arrival time, then queues
// them as one block. The batch's storage is reused read after read, so after the first reads
// nothing is allocated.
class InputReader::QueueSink final : public frontends::DecodeSink {
 public:
  explicit QueueSink(InputReader& reader) : reader_(reader) {}
  void begin(std::int64_t arrival_ns) {
    arrival_ns_ = arrival_ns;
    size_ = 0;
  }

  void on_measurement(const Measurement& m) override {
    if (size_ == batch_.size()) batch_.emplace_back();
    ArrivedMeasurement& item = batch_[size_++];
    item.measurement = m;
    item.arrival_ns = arrival_ns_;
    item.source = reader_.index_;
    header_of(item.measurement).stream_id = reader_.index_;
  }

  std::span<const ArrivedMeasurement> batch() const { return {batch_.data(), size_}; }

  void queue() {
    for (const ArrivedMeasurement& item : batch()) {
      if (reader_.pacer_ != nullptr) reader_.pacer_->wait(header_of(item.measurement), reader_.stop_);
      bool queued = false;
      if (reader_.live_) {
        queued = reader_.queue_.try_push(item);
      } else {
        while (!queued && !reader_.stop_.load(std::memory_order_relaxed)) {
          queued = reader_.queue_.push_wait(item, std::chrono::milliseconds(kReadTimeoutMs));
        }
      }
      (queued ? reader_.measurements_ : reader_.dropped_).fetch_add(1, std::memory_order_relaxed);
    }
    size_ = 0;
  }

 private:
  InputReader& reader_;
  std::vector<ArrivedMeasurement> batch_;
  std::size_t size_ = 0;
  std::int64_t arrival_ns_ = 0;
};

InputReader::InputReader(InputEndpoint endpoint, std::uint16_t index, MeasurementQueue& queue,
                         const config::Config* device_config, std::unique_ptr<StreamRecorder> recorder,
                         RealtimePacer* pacer)
    : endpoint_(std::move(endpoint)),
      index_(index),
      queue_(queue),
      device_config_(device_config),
      live_(!is_regular_file(endpoint_.uri)),
      sink_(std::make_unique<QueueSink>(*this)),
      recorder_(std::move(recorder)),
      pacer_(live_ ? nullptr : pacer) {
  try {
    transport_ = io::open_transport(endpoint_.uri, io::Direction::kInput);
  } catch (const io::TransportError& e) {
    throw CommandError("--in '" + endpoint_.text + "': " + e.what());
  }
  if (endpoint_.frontend != nullptr) {
    use_frontend(endpoint_.frontend);
    if (recorder_) recorder_->decoding(endpoint_.frontend->format, 0);
  }
  seen_reconnects_ = transport_->stats().reconnects;
  seen_errors_ = transport_->stats().errors;
}

InputReader::~InputReader() {
  request_stop();
  join();
}

void InputReader::start() { thread_ = std::thread([this] { run(); }); }

void InputReader::join() {
  if (thread_.joinable()) thread_.join();
}

std::string_view InputReader::format() const {
  const auto* f = frontend_.load(std::memory_order_acquire);
  return f != nullptr ? f->format : std::string_view{};
}

InputCounters InputReader::counters() const {
  constexpr auto r = std::memory_order_relaxed;
  return {bytes_.load(r),        frames_.load(r),  bad_frames_.load(r), measurements_.load(r),
          dropped_.load(r),      reconnects_.load(r), ended()};
}

void InputReader::use_frontend(const frontends::FrontendInfo* frontend) {
  decoder_ = frontend->make_decoder();
  frontend_.store(frontend, std::memory_order_release);
}

void InputReader::run() {
  std::array<std::uint8_t, kReadChunk> buffer{};
  // Paced reads are small, so that a read's block of measurements spans little time.
  const std::size_t read_size = pacer_ != nullptr ? kPacedReadChunk : buffer.size();
  if (device_config_ != nullptr && live_) configure_device();
  while (!stop_.load(std::memory_order_relaxed)) {
    const std::ptrdiff_t n = transport_->read(std::span(buffer.data(), read_size), kReadTimeoutMs);
    if (n == io::kEndOfStream) break;
    if (n > 0) ingest(std::span<const std::uint8_t>(buffer.data(), static_cast<std::size_t>(n)));
    watch_link();
    write_outgoing();
  }
  finish_stream();
  ended_.store(true, std::memory_order_release);
  if (!stop_.load(std::memory_order_relaxed)) log_event("input '" + endpoint_.text + "' ended");
}

void InputReader::ingest(std::span<const std::uint8_t> bytes) {
  const std::int64_t arrival_ns = monotonic_ns();
  sink_->begin(arrival_ns);
  decode(bytes);
  // The first wait outside the recorder's lock; the rest of a (small) paced read waits in queue().
  if (pacer_ != nullptr && !sink_->batch().empty()) pacer_->wait(header_of(sink_->batch().front().measurement), stop_);
  std::unique_lock<std::mutex> order;
  if (recorder_) {
    order = recorder_->read(bytes, arrival_ns);
    if (decode_started_from_) recorder_->decoding(format(), *decode_started_from_);
  }
  decode_started_from_.reset();
  sink_->queue();
}

void InputReader::finish_stream() {
  const std::int64_t now = monotonic_ns();
  sink_->begin(now);
  if (decoder_) {
    decoder_->finish(*sink_);
  } else if (!head_.empty()) {
    detect({}, /*at_end=*/true);
    if (decoder_) decoder_->finish(*sink_);
  }
  std::unique_lock<std::mutex> order;
  if (recorder_) {
    order = recorder_->end(now);
    // Detected only now: its measurements are queued with the end, so the decode line follows it.
    if (decode_started_from_) recorder_->decoding(format(), *decode_started_from_);
  }
  decode_started_from_.reset();
  sink_->queue();
  publish_counters();
}

void InputReader::decode(std::span<const std::uint8_t> bytes) {
  bytes_.fetch_add(bytes.size(), std::memory_order_relaxed);
  if (decoder_) {
    decoder_->feed(bytes, *sink_);
  } else {
    detect(bytes, /*at_end=*/false);
  }
  publish_counters();
}

void InputReader::detect(std::span<const std::uint8_t> bytes, bool at_end) {
  head_.insert(head_.end(), bytes.begin(), bytes.end());
  if (head_.size() < kDetectMinBytes && !at_end) return;
  if (const auto* f = detect_format(head_)) {
    log_event("input '" + endpoint_.text + "': detected format " + std::string(f->format));
    use_frontend(f);
    decode_started_from_ = bytes_.load(std::memory_order_relaxed) - head_.size();
    decoder_->feed(head_, *sink_);
    head_ = {};  // release the probe buffer: it is not needed again
    return;
  }
  if (!detection_failed_logged_ && (at_end || head_.size() >= kProbeBytes)) {
    log_event("input '" + endpoint_.text + "': no frame of " + known_formats() + " in the first " +
              std::to_string(head_.size()) + " bytes; give the format as FORMAT:URI");
    detection_failed_logged_ = true;
  }
  // Keep looking in a sliding window: a live device may start with noise or a boot banner.
  if (head_.size() >= kProbeBytes) head_.erase(head_.begin(), head_.begin() + kProbeBytes / 2);
}

void InputReader::watch_link() {
  const io::TransportStats& s = transport_->stats();
  if (s.errors != seen_errors_) {
    seen_errors_ = s.errors;
    if (transport_->is_open()) return;  // a transient error, the link is still up
    log_event("input '" + endpoint_.text + "' lost: " + s.last_error + "; re-opening");
  }
  if (s.reconnects != seen_reconnects_) {
    seen_reconnects_ = s.reconnects;
    reconnects_.store(s.reconnects, std::memory_order_relaxed);
    log_event("input '" + endpoint_.text + "' re-opened");
    if (device_config_ != nullptr) configure_device();
  }
}

void InputReader::configure_device() {
  const std::string_view fmt = format();
  const std::vector<SetupStep> steps = device_setup_steps(fmt, *device_config_);
  if (steps.empty()) return;
  transport_->wait_open(static_cast<int>(kReplyTimeout.count()));
  std::array<std::uint8_t, kReadChunk> buffer{};
  std::vector<std::uint8_t> reply;
  std::size_t verified = 0;
  for (const SetupStep& step : steps) {
    if (transport_->write(step.command) <= 0) {
      log_event("input '" + endpoint_.text + "': cannot send the device set-up (link down)");
      return;
    }
    // Read the answer (and whatever the device streams meanwhile, which is decoded as usual).
    // A read-back waits for the reply it checks, not just for a quiet gap: a device streaming
    // at 10 Hz is quiet for longer than the gap before its answer comes.
    reply.clear();
    const auto deadline = std::chrono::steady_clock::now() + kReplyTimeout;
    while (std::chrono::steady_clock::now() < deadline && !stop_.load(std::memory_order_relaxed)) {
      const int wait = reply.empty() ? kReadTimeoutMs : kReplyQuietMs;
      const std::ptrdiff_t n = transport_->read(buffer, wait);
      if (n <= 0) {
        if (!reply.empty() && !step.verify) break;
        continue;
      }
      const std::span<const std::uint8_t> got(buffer.data(), static_cast<std::size_t>(n));
      reply.insert(reply.end(), got.begin(), got.end());
      ingest(got);
      if (step.verify && step.verify(reply).empty()) break;
    }
    if (const std::string why = find_refusal(fmt, reply); !why.empty()) {
      fail_setup("device refused a set-up command: " + why + (step.sets.empty() ? "" : " (setting " + step.sets + ")"));
      return;
    }
    if (step.verify) {
      if (const std::string why = step.verify(reply); !why.empty()) {
        fail_setup("device set-up not verified: " + why);
        return;
      }
      ++verified;
    }
  }
  log_event("input '" + endpoint_.text + "': sent the " + std::string(fmt) + " device set-up (" +
            std::to_string(steps.size()) + " commands, none refused; " + std::to_string(verified) +
            " settings read back as written)");
}

void InputReader::fail_setup(const std::string& why) {
  const std::string what = "input '" + endpoint_.text + "': " + why;
  log_event(what);
  {
    std::lock_guard lock(setup_error_mutex_);
    setup_error_ = what;
  }
  // Navigating on a device that is not set up as configured would give wrong results with no
  // sign of it: this input ends here and the nav process stops with the error (issue 17).
  setup_failed_.store(true, std::memory_order_release);
  request_stop();
}

std::string InputReader::setup_error() const {
  std::lock_guard lock(setup_error_mutex_);
  return setup_error_;
}

std::size_t InputReader::send(std::span<const std::uint8_t> bytes) {
  std::lock_guard lock(outgoing_mutex_);
  if (outgoing_.size() + bytes.size() > kMaxOutgoingBytes) return 0;
  outgoing_.insert(outgoing_.end(), bytes.begin(), bytes.end());
  return bytes.size();
}

void InputReader::write_outgoing() {
  {
    std::lock_guard lock(outgoing_mutex_);
    if (outgoing_.empty()) return;
    writing_.swap(outgoing_);
  }
  if (transport_->write(writing_) <= 0 && !outgoing_failure_logged_) {
    log_event("input '" + endpoint_.text + "': cannot write to the device (" +
              (transport_->is_open() ? "write refused" : "link down") + "); bytes for it are dropped");
    outgoing_failure_logged_ = true;
  }
  writing_.clear();
}

void InputReader::publish_counters() {
  if (!decoder_) return;
  const frontends::StreamCounters& c = decoder_->counters();
  frames_.store(c.frames, std::memory_order_relaxed);
  bad_frames_.store(c.bad_frames, std::memory_order_relaxed);
}

}  // namespace navfuse::apps
