#include "apps/output/fe_stream_rates.hpp"

namespace navfuse::apps {
namespace {

using fe::MessageRate;
using fe::MessageType;

// Period of an interval rate (spec L1419-1440), 0 for the others.
double period_s(MessageRate rate) {
  switch (rate) {
    case MessageRate::k10Ms: return 0.01;
    case MessageRate::k20Ms: return 0.02;
    case MessageRate::k40Ms: return 0.04;
    case MessageRate::k50Ms: return 0.05;
    case MessageRate::k100Ms: return 0.1;
    case MessageRate::k200Ms: return 0.2;
    case MessageRate::k500Ms: return 0.5;
    case MessageRate::k1S: return 1.0;
    case MessageRate::k2S: return 2.0;
    case MessageRate::k5S: return 5.0;
    case MessageRate::k10S: return 10.0;
    case MessageRate::k30S: return 30.0;
    case MessageRate::k60S: return 60.0;
    default: return 0.0;
  }
}

}  // namespace

FeStreamRates::FeStreamRates()
    : entries_{{{MessageType::kPose}, {MessageType::kPoseAux}, {MessageType::kGnssInfo}, {MessageType::kImuOutput}}} {}

FeStreamRates::Entry* FeStreamRates::find(MessageType type) {
  for (Entry& e : entries_) {
    if (e.type == type) return &e;
  }
  return nullptr;
}

fe::MessageRate FeStreamRates::rate(MessageType type) const {
  for (const Entry& e : entries_) {
    if (e.type == type) return e.rate;
  }
  return MessageRate::kOff;
}

bool FeStreamRates::set(std::uint16_t message_id, MessageRate rate) {
  const auto apply = [rate](Entry& e) {
    e.rate = rate;
    const double p = period_s(rate);
    e.interval = OutputRate(p > 0 ? 1.0 / p : 0.0);
  };
  if (message_id == fe::kAllMessages) {
    for (Entry& e : entries_) apply(e);
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
