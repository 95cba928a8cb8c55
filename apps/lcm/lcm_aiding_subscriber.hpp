// Subscribes to the aiding channels (DESIGN.md: NAVFUSE_AID_POSITION, _VELOCITY, _HEADING,
// _SPEED) on a caller-owned lcm::LCM and hands every received message to a sink as a core
// measurement (apps/aid/aid_message.hpp to_measurement). Messages are delivered from inside
// lcm::LCM::handle(), i.e. on the thread that services the handle.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "core/measurements/measurements.hpp"
#include "navfuse/aid_heading_t.hpp"
#include "navfuse/aid_position_t.hpp"
#include "navfuse/aid_speed_t.hpp"
#include "navfuse/aid_velocity_t.hpp"

namespace navfuse::apps {

class LcmAidingSubscriber {
 public:
  using Sink = std::function<void(const Measurement&)>;

  LcmAidingSubscriber(lcm::LCM& lcm, Sink sink);
  ~LcmAidingSubscriber();
  LcmAidingSubscriber(const LcmAidingSubscriber&) = delete;
  LcmAidingSubscriber& operator=(const LcmAidingSubscriber&) = delete;

  std::uint64_t received() const { return received_; }

 private:
  template <class Message>
  void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel, const Message* msg);

  lcm::LCM& lcm_;
  Sink sink_;
  std::array<lcm::Subscription*, 4> subscriptions_{};
  std::uint64_t received_ = 0;
};

}  // namespace navfuse::apps
