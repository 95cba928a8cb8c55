#include "apps/run/lcm_service.hpp"

#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "apps/common/command_error.hpp"
#include "apps/lcm/lcm_open.hpp"
#include "apps/run/run_log.hpp"

namespace navfuse::apps {
namespace {

constexpr std::size_t kOutboxCapacity = 1024;  // ~2.5 s of a 400 Hz IMU stream
constexpr int kIdlePollMs = 200;               // only bounds how late a stop() is noticed

}  // namespace

LcmService::LcmService(const std::string& url, MeasurementQueue& aiding_queue, LatencyTracker& latency)
    : lcm_(url),
      publisher_(lcm_),
      aiding_queue_(aiding_queue),
      latency_(latency),
      outbox_(kOutboxCapacity),
      wake_fd_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
  require_lcm_open(lcm_, url);
  if (!wake_fd_) throw CommandError(std::string("--lcm: eventfd: ") + std::strerror(errno));
  subscriber_ = std::make_unique<LcmAidingSubscriber>(lcm_, [this](const Measurement& m) { on_aiding(m); });
  aiding_item_.source = kSourceLcmAiding;
}

LcmService::~LcmService() { stop(); }

void LcmService::start() { thread_ = std::thread([this] { run(); }); }

void LcmService::stop() {
  if (!thread_.joinable()) return;
  stop_.store(true, std::memory_order_relaxed);
  wake();
  thread_.join();
}

void LcmService::wake() {
  const std::uint64_t one = 1;
  // EAGAIN means the counter is already non-zero: the thread is due to wake anyway.
  [[maybe_unused]] const ssize_t n = ::write(wake_fd_.get(), &one, sizeof one);
}

bool LcmService::post(const Outgoing& item) {
  if (!outbox_.try_push(item)) {
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  wake();
  return true;
}

bool LcmService::post_epoch(const OutputEpoch& epoch) {
  if (!LcmPublisher::publishes(epoch)) return true;
  scratch_.emplace<OutputEpoch>(epoch);
  return post(scratch_);
}

bool LcmService::post_gnss(const GnssPosition& p, const GnssVelocity* v) {
  auto& out = scratch_.emplace<lcm_outbox::Gnss>();
  out.position = p;
  out.has_velocity = v != nullptr;
  if (v != nullptr) out.velocity = *v;
  return post(scratch_);
}

void LcmService::post_status(navfuse::status_t status) {
  {
    std::lock_guard lock(status_mutex_);
    status_ = std::move(status);
  }
  wake();
}

void LcmService::run() {
  pollfd fds[2] = {{lcm_.getFileno(), POLLIN, 0}, {wake_fd_.get(), POLLIN, 0}};
  for (;;) {
    const int ready = ::poll(fds, 2, kIdlePollMs);
    if (ready < 0 && errno != EINTR) {
      log_event(std::string("LCM thread: poll: ") + std::strerror(errno));
      break;
    }
    if (fds[1].revents & POLLIN) {
      std::uint64_t count = 0;
      [[maybe_unused]] const ssize_t n = ::read(wake_fd_.get(), &count, sizeof count);
    }
    publish_pending();
    if (fds[0].revents & POLLIN) lcm_.handle();  // readable: returns without waiting
    if (stop_.load(std::memory_order_relaxed)) break;
  }
  publish_pending();
}

void LcmService::publish_pending() {
  while (outbox_.try_pop(current_)) publish(current_);
  std::optional<navfuse::status_t> status;
  {
    std::lock_guard lock(status_mutex_);
    status.swap(status_);
  }
  if (status) publisher_.publish_status(*status);
}

void LcmService::publish(const Outgoing& item) {
  if (const auto* epoch = std::get_if<OutputEpoch>(&item)) {
    if (publisher_.publish_epoch(*epoch)) latency_.record(monotonic_ns() - epoch->arrival_ns);
  } else if (const auto* gnss = std::get_if<lcm_outbox::Gnss>(&item)) {
    publisher_.publish_gnss(gnss->position, gnss->has_velocity ? &gnss->velocity : nullptr);
  }
}

void LcmService::on_aiding(const Measurement& m) {
  aiding_received_.fetch_add(1, std::memory_order_relaxed);
  aiding_item_.measurement = m;
  aiding_item_.arrival_ns = monotonic_ns();
  if (!aiding_queue_.try_push(aiding_item_)) aiding_dropped_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace navfuse::apps
