// The protocol an output link speaks: navfuse stands in for a device (a Point One FusionEngine
// receiver on --fe-out, a MicroStrain CV7 on --mip-out), so software written for that device
// reads its stream and sends it commands unchanged.
//
// An emulator is used by one output thread only, which owns the link: it needs no locking, and
// its state (message rates, sequence numbers, per-client framers) lives with the stream it shapes.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "apps/run/engine_action.hpp"
#include "apps/fusion/output_epoch.hpp"
#include "core/io/transport.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

// What the commands of one receive() ask of the rest of the nav process.
struct CommandEffects {
  std::vector<Measurement> aiding;    // to fuse: MIP 0x13 aiding, FusionEngine sensor inputs
  std::vector<EngineAction> actions;  // resets, lever arms, mounting
  void clear() {
    aiding.clear();
    actions.clear();
  }
};

class DeviceEmulator {
 public:
  virtual ~DeviceEmulator() = default;
  // "fe" or "mip", for messages.
  virtual std::string_view protocol() const = 0;
  // Appends the bytes the device streams after this IMU epoch (often none: rates decide).
  virtual void stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) = 0;
  // Bytes a client sent on the link, in arbitrary chunks. Appends the answer for that client to
  // `reply` (what the device would send back) and what the commands ask for to `effects`.
  virtual void receive(io::PeerId peer, std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& reply,
                       CommandEffects& effects) = 0;
};

}  // namespace navfuse::apps
