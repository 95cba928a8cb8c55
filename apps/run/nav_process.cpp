#include "apps/run/nav_process.hpp"

#include <chrono>

#include "apps/common/command_error.hpp"
#include "apps/output/csv_pose_writer.hpp"
#include "apps/output/output_paths.hpp"
#include "apps/run/fe_device_emulator.hpp"
#include "apps/run/mip_device_emulator.hpp"
#include "apps/run/nmea_output_link.hpp"
#include "apps/run/run_log.hpp"
#include "core/rotation/rotation.hpp"
#include "frontends/common/setup_step.hpp"

namespace navfuse::apps {
namespace {

// ~10 s of a 400 Hz IMU with its GNSS: room for a filter restart or a burst from a file input.
constexpr std::size_t kQueueCapacity = 4096;
constexpr std::size_t kActionQueueCapacity = 64;
// How long the filter thread waits for a measurement before it looks at status and shutdown.
constexpr auto kFilterWait = std::chrono::milliseconds(20);
// Position and velocity of one GNSS epoch are decoded as two measurements; within this they
// are one NAVFUSE_GNSS message.
constexpr std::int64_t kSameEpochNs = 1'000'000;

using frontends::vector_text;

config::Config load_config(const std::string& path) {
  if (path.empty()) throw CommandError("run needs --config FILE");
  try {
    return config::load_from_file(path);
  } catch (const config::ConfigError& e) {
    throw CommandError(e.what());
  }
}

}  // namespace

NavProcess::NavProcess(const RunOptions& options)
    : options_(options),
      config_(load_config(options.config_path)),
      queue_(kQueueCapacity),
      actions_(kActionQueueCapacity) {
  if (options_.inputs.empty()) throw CommandError("run needs at least one INPUT (or --in URI)");
  if (!(options_.status_interval_s > 0)) throw CommandError("--status-interval must be > 0 s");
  runner_ = std::make_unique<FusionRunner>(
      filter::options_from_config(config_),
      FusionRunner::Options{.output_rate_hz = config_.output.rate_hz,
                            .solutions = FusionRunner::Solutions::kEvery,
                            .gnss_outages = std::nullopt},
      static_cast<FusionObserver&>(*this));

  // Parse every argument before opening anything: a typo in the last --in is reported without
  // first grabbing serial ports and sockets for the others.
  std::vector<InputEndpoint> endpoints;
  for (const std::string& arg : options_.inputs) endpoints.push_back(parse_input_endpoint(arg));
  const io::Uri fe_uri = options_.fe_out.empty() ? io::Uri{} : parse_output_uri(options_.fe_out, "--fe-out");
  const io::Uri mip_uri = options_.mip_out.empty() ? io::Uri{} : parse_output_uri(options_.mip_out, "--mip-out");
  const io::Uri nmea_uri =
      options_.nmea_out.empty() ? io::Uri{} : parse_output_uri(options_.nmea_out, "--nmea-out");
  if (!options_.csv_out.empty()) {
    std::vector<std::string> input_paths;
    for (const InputEndpoint& e : endpoints) {
      if (e.uri.scheme == io::Scheme::kFile) input_paths.push_back(e.uri.path);
    }
    check_output_paths(input_paths, {{"--csv", options_.csv_out}});
  }
  if (options_.configure_device) {
    for (const InputEndpoint& e : endpoints) {
      if (e.frontend == nullptr && e.uri.scheme != io::Scheme::kFile) {
        throw CommandError("--configure-device: give the format of '" + e.text +
                           "' (FORMAT:URI): a device is set up before it streams anything to detect");
      }
    }
  }

  if (options_.realtime_speed < 0.0) throw CommandError("--realtime: the speed must be > 0");
  if (options_.realtime_speed > 0.0) pacer_ = std::make_unique<RealtimePacer>(options_.realtime_speed);
  if (!options_.record_dir.empty()) {
    recorder_ = std::make_unique<RunRecorder>(options_.record_dir, options_.config_path, options_.inputs);
  }
  for (std::size_t i = 0; i < endpoints.size(); ++i) {
    auto recorder = recorder_ ? recorder_->open_stream(i, endpoints[i].text) : nullptr;
    inputs_.push_back(std::make_unique<InputReader>(std::move(endpoints[i]), static_cast<std::uint16_t>(i), queue_,
                                                    options_.configure_device ? &config_ : nullptr, std::move(recorder),
                                                    pacer_.get()));
  }
  if (!options_.fe_out.empty()) {
    outputs_.push_back(std::make_unique<OutputSink>(
        "--fe-out", fe_uri, make_fe_device_emulator(config_, fe_uri.scheme != io::Scheme::kFile), queue_, actions_));
  }
  if (!options_.mip_out.empty()) {
    const filter::FilterOptions filter_options = filter::options_from_config(config_);
    outputs_.push_back(
        std::make_unique<OutputSink>("--mip-out", mip_uri,
                                     std::make_unique<MipDeviceEmulator>(filter_options.mounting_rpy_rad,
                                                                         filter_options.gnss_lever_arm_m,
                                                                         mip_uri.scheme != io::Scheme::kFile),
                                     queue_, actions_));
  }
  if (!options_.nmea_out.empty()) {
    outputs_.push_back(
        std::make_unique<OutputSink>("--nmea-out", nmea_uri, std::make_unique<NmeaOutputLink>(), queue_, actions_));
  }
  if (!options_.csv_out.empty()) files_.add(std::make_unique<CsvPoseWriter>(options_.csv_out));
  if (options_.lcm) lcm_ = std::make_unique<LcmService>(options_.lcm_url, queue_, latency_);
  if (!options_.corrections.empty()) {
    if (options_.corrections_to < 0 || static_cast<std::size_t>(options_.corrections_to) >= inputs_.size()) {
      throw CommandError("--corrections-to " + std::to_string(options_.corrections_to) + ": there are " +
                         std::to_string(inputs_.size()) + " inputs, numbered from 0");
    }
    CorrectionsSource source = parse_corrections_source(options_.corrections);
    if (source.gga_interval_s > 0.0) rover_ = std::make_unique<RoverPosition>();
    corrections_ = std::make_unique<CorrectionsForwarder>(
        std::move(source), *inputs_[static_cast<std::size_t>(options_.corrections_to)], rover_.get());
  }
  for (const auto& in : inputs_) snapshots_.push_back({in->name(), {}});
}

NavProcess::~NavProcess() { stop(); }

void NavProcess::start() {
  started_ns_ = monotonic_ns();
  next_status_ns_ = started_ns_ + static_cast<std::int64_t>(options_.status_interval_s * 1e9);
  if (lcm_) lcm_->start();
  for (auto& out : outputs_) out->start();
  if (!files_.empty()) file_thread_ = std::make_unique<PoseOutputThread>(files_);
  filter_thread_ = std::thread([this] { filter_loop(); });
  for (auto& in : inputs_) in->start();
  if (corrections_) corrections_->start();
}

void NavProcess::stop() {
  if (stopped_ || !filter_thread_.joinable()) return;
  stopped_ = true;
  if (corrections_) corrections_->stop();
  // Producers first, then the filter drains the queue, then the consumers of its output flush.
  for (auto& in : inputs_) in->request_stop();
  for (auto& in : inputs_) in->join();
  stop_filter_.store(true, std::memory_order_relaxed);
  filter_thread_.join();
  stopped_ns_ = monotonic_ns();
  for (auto& out : outputs_) out->stop();
  if (lcm_) lcm_->stop();
  if (file_thread_ && !file_failed_) {
    try {
      file_thread_->finish();
      files_.commit();
    } catch (const CommandError& e) {
      log_event(e.what());
    }
  }
}

bool NavProcess::inputs_ended() const {
  for (const auto& in : inputs_) {
    if (!in->ended()) return false;
  }
  return true;
}

void NavProcess::filter_loop() {
  for (;;) {
    const bool got = queue_.pop_wait(item_, kFilterWait);
    apply_actions();
    if (got) runner_->offer(item_.measurement, item_.arrival_ns);
    if (monotonic_ns() >= next_status_ns_) report_status();
    if (got) continue;
    // Nothing queued: done when told to stop, or when every input has ended (an input marks
    // itself ended only after queueing its last measurement, so the queue is then final).
    if (stop_filter_.load(std::memory_order_relaxed) && queue_.empty()) break;
    if (inputs_ended() && queue_.empty()) {
      finished_.store(true, std::memory_order_release);
      if (stop_filter_.load(std::memory_order_relaxed)) break;
    }
  }
  runner_->finish();
  report_status();  // the final state, for whoever watches NAVFUSE_STATUS
}

void NavProcess::on_fused(const Measurement& m) {
  if (lcm_) track_gnss(m);
}

void NavProcess::on_epoch(const OutputEpoch& epoch, const filter::Engine&) {
  for (auto& out : outputs_) out->post(epoch);
  if (file_thread_ && !file_failed_) {
    // A file that cannot be written (disk full) ends that output, not the nav process.
    try {
      file_thread_->post(epoch);
    } catch (const CommandError& e) {
      log_event(e.what());
      file_failed_ = true;
    }
  }
  if (lcm_) lcm_->post_epoch(epoch);
  if (rover_) rover_->update(epoch);
}

void NavProcess::track_gnss(const Measurement& m) {
  if (const auto* p = std::get_if<GnssPosition>(&m)) {
    if (fix_pending_) lcm_->post_gnss(pending_fix_, nullptr);  // its velocity never came
    pending_fix_ = *p;
    fix_pending_ = true;
  } else if (const auto* v = std::get_if<GnssVelocity>(&m)) {
    if (fix_pending_ && v->receiver_id == pending_fix_.receiver_id &&
        std::llabs(v->header.time_ns - pending_fix_.header.time_ns) < kSameEpochNs) {
      lcm_->post_gnss(pending_fix_, v);
      fix_pending_ = false;
    }
  }
}

void NavProcess::apply_actions() {
  EngineAction a;
  while (actions_.try_pop(a)) {
    switch (a.kind) {
      case EngineAction::Kind::kReset:
        runner_->engine().reset(a.reset_mask);
        log_event("filter reset by command (mask " + std::to_string(a.reset_mask) + ")");
        break;
      // Installation geometry a client set on an output link: logged, so that whoever configured
      // navfuse as a device can see what it took (run --configure-device of another process).
      case EngineAction::Kind::kGnssLeverArm:
        runner_->engine().set_gnss_lever_arm(a.vector, a.antenna);
        log_event("GNSS lever arm of antenna " + std::to_string(a.antenna) + " set by command to " +
                  vector_text(a.vector) + " m (vehicle FRD)");
        break;
      case EngineAction::Kind::kMounting:
        runner_->engine().set_mounting(a.vector);
        log_event("mounting set by command to roll, pitch, yaw " + vector_text(a.vector * rot::kRadToDeg) + " deg");
        break;
      case EngineAction::Kind::kWheelLeverArm:
        runner_->engine().set_wheel_lever_arm(a.vector);
        log_event("wheel lever arm set by command to " + vector_text(a.vector) + " m (vehicle FRD)");
        break;
      case EngineAction::Kind::kNonholonomic: runner_->engine().set_nonholonomic(a.enable); break;
      case EngineAction::Kind::kAiding: runner_->engine().set_aiding(a.aiding, a.enable); break;
      case EngineAction::Kind::kInitialHeading:
        if (!runner_->engine().set_initial_heading(a.heading_rad)) {
          log_event("initial heading command ignored: heading known or magnetometer aiding on");
        }
        break;
    }
  }
}

void NavProcess::report_status() {
  const std::int64_t now = monotonic_ns();
  next_status_ns_ = now + static_cast<std::int64_t>(options_.status_interval_s * 1e9);
  if (!lcm_) return;
  std::uint64_t queue_full = 0;
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    snapshots_[i].counters = inputs_[i]->counters();
    queue_full += snapshots_[i].counters.dropped;
  }
  queue_full += lcm_->aiding_dropped();
  std::uint64_t output_drops = lcm_->dropped();
  for (const auto& out : outputs_) output_drops += out->drops();
  const filter::Engine& engine = runner_->engine();
  const StatusInputs in{engine.solution(), engine.stats(), snapshots_, queue_full, runner_->gated_total(),
                        output_drops, latency_.take_window()};
  lcm_->post_status(status_.make(in, now));
}

std::string NavProcess::setup_error() const {
  for (const auto& in : inputs_) {
    if (in->setup_failed()) return in->setup_error();
  }
  return {};
}

std::vector<std::string> NavProcess::output_errors() const {
  std::vector<std::string> errors;
  for (const auto& out : outputs_) {
    if (std::string e = out->write_error(); !e.empty()) errors.push_back(std::move(e));
  }
  return errors;
}

Summary NavProcess::summary() const {
  Summary s;
  for (const auto& in : inputs_) {
    const InputCounters c = in->counters();
    InputSummary is;
    is.path = in->name();
    is.format = std::string(in->format());
    is.counters.bytes = c.bytes;
    is.counters.frames = c.frames;
    is.counters.bad_frames = c.bad_frames;
    s.inputs.push_back(std::move(is));
  }
  const std::int64_t end_ns = stopped_ns_ > 0 ? stopped_ns_ : monotonic_ns();
  runner_->fill_summary(s, started_ns_ > 0 ? static_cast<double>(end_ns - started_ns_) * 1e-9 : 0.0);
  if (corrections_) s.extra["corrections"] = corrections_->counters();
  return s;
}

}  // namespace navfuse::apps
