#include "apps/output/fe_stream_rates.hpp"

namespace navfuse::apps {

using frontends::fusionengine::MessageRate;
using frontends::fusionengine::MessageType;

FeStreamRates::FeStreamRates()
    : entries_{{{MessageType::kPose},
                {MessageType::kPoseAux},
                {MessageType::kGnssInfo},
                {MessageType::kImuOutput},
                {MessageType::kCalibrationStatus},
                {MessageType::kSystemStatus}}} {}

FeStreamRates::Entry* FeStreamRates::find(MessageType type) {
  for (Entry& e : entries_) {
    if (e.type == type) return &e;
  }
  return nullptr;
}

frontends::fusionengine::MessageRate FeStreamRates::rate(MessageType type) const {
  for (const Entry& e : entries_) {
    if (e.type == type) return e.rate;
  }
  return MessageRate::kOff;
}

void FeStreamRates::assign(Entry& e, MessageRate rate) {
  e.rate = rate;
  const double p = frontends::fusionengine::interval_s(rate);
  e.interval = OutputRate(p > 0 ? 1.0 / p : 0.0);
}

void FeStreamRates::save() {
  for (Entry& e : entries_) e.saved = e.rate;
}

void FeStreamRates::revert_to_saved() {
  for (Entry& e : entries_) assign(e, e.saved);
}

void FeStreamRates::revert_to_default() {
  for (Entry& e : entries_) {
    e.saved = MessageRate::kDefault;
    assign(e, MessageRate::kDefault);
  }
}

bool FeStreamRates::set(std::uint16_t message_id, MessageRate rate, bool include_disabled, bool and_save) {
  const auto apply = [rate, and_save](Entry& e) {
    assign(e, rate);
    if (and_save) e.saved = rate;
  };
  if (message_id == frontends::fusionengine::kAllMessages) {
    const bool interval = frontends::fusionengine::interval_s(rate) > 0;
    for (Entry& e : entries_) {
      if (interval && !include_disabled && e.rate == MessageRate::kOff) continue;
      apply(e);
    }
    return true;
  }
  Entry* e = find(static_cast<MessageType>(message_id));
  if (e == nullptr) return false;
  apply(*e);
  return true;
}

bool FeStreamRates::due(MessageType type, std::int64_t time_ns, bool default_due, bool on_change) {
  Entry* e = find(type);
  if (e == nullptr) return false;
  switch (e->rate) {
    case MessageRate::kOff: return false;
    case MessageRate::kDefault: return default_due;
    case MessageRate::kOnChange: return on_change;
    default: return e->interval.due(time_ns);
  }
}

}  // namespace navfuse::apps
