#include "apps/run/fe_link_inputs.hpp"

#include "frontends/fusionengine/message_versions.hpp"
#include "frontends/fusionengine/messages_sensor.hpp"
#include "frontends/fusionengine/payload_reader.hpp"

namespace navfuse::apps {
namespace {

namespace fe = frontends::fusionengine;

// Collects what the mapper emits for one frame, giving a time of arrival to what has none.
struct Collect final : frontends::DecodeSink {
  std::vector<Measurement>& out;
  const std::optional<std::int64_t>& now_ns;
  Collect(std::vector<Measurement>& o, const std::optional<std::int64_t>& now) : out(o), now_ns(now) {}
  void on_measurement(const Measurement& m) override {
    MeasurementHeader& h = header_of(out.emplace_back(m));
    if (h.time_source == TimeSource::kUnknown && now_ns) {
      h.time_ns = *now_ns;
      h.time_source = TimeSource::kGps;
    }
  }
};

template <class M>
bool decode_as(const fe::Frame& frame, fe::MeasurementMapper& mapper, frontends::DecodeSink& sink) {
  M msg;
  if (!fe::decode_payload(frame.payload, msg) || !fe::adapt_to_version(msg, frame.header.message_version)) {
    return false;
  }
  msg.details.p1_time = fe::Timestamp{};  // "Any value in the P1 time field will be ignored" (L302)
  mapper.on(msg, sink);
  return true;
}

}  // namespace

FeLinkInputs::FeLinkInputs() { mapper_.set_gps_minus_p1_ns(0); }

bool FeLinkInputs::decode(const fe::Frame& frame, std::vector<Measurement>& out) {
  Collect sink(out, now_ns_);
  bool ok = false;
  switch (static_cast<fe::MessageType>(frame.header.message_type)) {
    case fe::MessageType::kImuInput: ok = decode_as<fe::ImuInputMessage>(frame, mapper_, sink); break;
    case fe::MessageType::kWheelSpeedInput: ok = decode_as<fe::WheelSpeedInputMessage>(frame, mapper_, sink); break;
    case fe::MessageType::kVehicleSpeedInput: ok = decode_as<fe::VehicleSpeedInputMessage>(frame, mapper_, sink); break;
    case fe::MessageType::kWheelTickInput: ok = decode_as<fe::WheelTickInputMessage>(frame, mapper_, sink); break;
    case fe::MessageType::kVehicleTickInput: ok = decode_as<fe::VehicleTickInputMessage>(frame, mapper_, sink); break;
    default: return false;
  }
  if (!ok) ++decode_errors_;
  return true;
}

}  // namespace navfuse::apps
