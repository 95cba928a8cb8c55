#include "apps/lcm/lcm_aiding_subscriber.hpp"

#include <utility>

#include "apps/aid/aid_message.hpp"

namespace navfuse::apps {

LcmAidingSubscriber::LcmAidingSubscriber(lcm::LCM& lcm, Sink sink) : lcm_(lcm), sink_(std::move(sink)) {
  using Self = LcmAidingSubscriber;
  subscriptions_ = {
      lcm_.subscribe(kAidPositionChannel, &Self::on_message<navfuse::aid_position_t>, this),
      lcm_.subscribe(kAidVelocityChannel, &Self::on_message<navfuse::aid_velocity_t>, this),
      lcm_.subscribe(kAidHeadingChannel, &Self::on_message<navfuse::aid_heading_t>, this),
      lcm_.subscribe(kAidSpeedChannel, &Self::on_message<navfuse::aid_speed_t>, this),
  };
}

LcmAidingSubscriber::~LcmAidingSubscriber() {
  for (lcm::Subscription* s : subscriptions_) {
    if (s != nullptr) lcm_.unsubscribe(s);
  }
}

template <class Message>
void LcmAidingSubscriber::on_message(const lcm::ReceiveBuffer*, const std::string&, const Message* msg) {
  ++received_;
  // The variant is built from the concrete measurement type to_measurement() returns.
  const Measurement m{to_measurement(*msg)};
  sink_(m);
}

}  // namespace navfuse::apps
