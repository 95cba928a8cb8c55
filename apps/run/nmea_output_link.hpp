// The --nmea-out link of `navfuse run`: navfuse as the NMEA talker of a GNSS receiver, for
// autopilots and generic GNSS consumers. It streams GGA/RMC/HDT (apps/output/
// nmea_epoch_encoder.hpp, the encoder of replay's --nmea-out file too) and, like a receiver's
// output-only NMEA port, takes no commands: what a client sends is dropped.
#pragma once

#include "apps/output/nmea_epoch_encoder.hpp"
#include "apps/run/device_emulator.hpp"

namespace navfuse::apps {

class NmeaOutputLink final : public DeviceEmulator {
 public:
  std::string_view protocol() const override { return "nmea"; }
  void stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) override { encoder_.append(epoch, out); }
  void receive(io::PeerId, std::span<const std::uint8_t>, std::vector<std::uint8_t>&, CommandEffects&) override {}

 private:
  NmeaEpochEncoder encoder_;
};

}  // namespace navfuse::apps
