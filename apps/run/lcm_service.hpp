// The nav process's LCM thread (`navfuse run --lcm [URL]`). It owns the lcm::LCM handle — LCM
// handles are serviced from one thread — and does both directions:
//  - publishes what the filter thread posts: output epochs (NAVFUSE_POSE and NAVFUSE_IMU at the
//    pose rate, through LcmPublisher::publish_epoch as `replay --lcm` does), GNSS fixes
//    (NAVFUSE_GNSS) and status (NAVFUSE_STATUS), recording for each pose the latency since its
//    IMU sample arrived;
//  - receives aiding on NAVFUSE_AID_* and queues it for the filter like any input.
// Posting never waits: the outbox is bounded and a full one drops (counted), so a stalled LCM
// send can never hold up the filter. The thread sleeps in poll(2) on the LCM socket and an
// eventfd that posting signals, so publication follows a post within microseconds.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <variant>

#include <lcm/lcm-cpp.hpp>

#include "apps/lcm/lcm_aiding_subscriber.hpp"
#include "apps/lcm/lcm_publisher.hpp"
#include "apps/fusion/output_epoch.hpp"
#include "apps/run/arrived_measurement.hpp"
#include "apps/run/latency_tracker.hpp"
#include "core/io/unique_fd.hpp"
#include "navfuse/status_t.hpp"

namespace navfuse::apps {

// A GNSS fix posted for publication (outside LcmService: a variant of nested classes with member
// initialisers cannot be default-constructed inside the enclosing class).
namespace lcm_outbox {
struct Gnss {
  GnssPosition position;
  GnssVelocity velocity;
  bool has_velocity = false;
};
}  // namespace lcm_outbox

class LcmService {
 public:
  // Opens LCM at `url` ("" = LCM's default); throws CommandError naming the URL if it cannot.
  LcmService(const std::string& url, MeasurementQueue& aiding_queue, LatencyTracker& latency);
  ~LcmService();
  LcmService(const LcmService&) = delete;
  LcmService& operator=(const LcmService&) = delete;

  void start();
  // Publishes what is still queued, then stops the thread.
  void stop();

  // Called by one thread, the filter's; each returns false when the message was dropped.
  // Every output epoch may be posted; only those LcmPublisher publishes are queued.
  bool post_epoch(const OutputEpoch& epoch);
  bool post_gnss(const GnssPosition& p, const GnssVelocity* v);
  // Only the newest status is kept: a status that could not go out yet is superseded.
  void post_status(navfuse::status_t status);

  std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }
  std::uint64_t aiding_received() const { return aiding_received_.load(std::memory_order_relaxed); }
  std::uint64_t aiding_dropped() const { return aiding_dropped_.load(std::memory_order_relaxed); }

 private:
  using Outgoing = std::variant<OutputEpoch, lcm_outbox::Gnss>;

  bool post(const Outgoing& item);
  void wake();
  void run();
  void publish_pending();
  void publish(const Outgoing& item);
  void on_aiding(const Measurement& m);

  lcm::LCM lcm_;
  LcmPublisher publisher_;
  MeasurementQueue& aiding_queue_;
  LatencyTracker& latency_;
  std::unique_ptr<LcmAidingSubscriber> subscriber_;
  BoundedQueue<Outgoing> outbox_;
  Outgoing scratch_;  // filled by the (single) filter thread before posting, reused
  Outgoing current_;  // popped by the LCM thread (reused)
  io::UniqueFd wake_fd_;

  std::mutex status_mutex_;
  std::optional<navfuse::status_t> status_;

  ArrivedMeasurement aiding_item_;  // LCM thread only
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> dropped_{0}, aiding_received_{0}, aiding_dropped_{0};
};

}  // namespace navfuse::apps
