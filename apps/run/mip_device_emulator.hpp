// --mip-out: navfuse as a CV7 on the link. Streams what replay's --mip-out file holds (the filter
// data set 0x82 at each pose, apps/output/mip_epoch_encoder.hpp) unless a client disabled that
// stream or set the device idle, and answers MIP commands as the CV7 does (frontends/mip/responder.hpp):
// external aiding (0x13) is handed to the filter, and the filter commands with an effect on the
// estimate — reset (0x0D,0x01), initial heading (0x0D,0x03), sensor-to-vehicle rotation (0x0C,0x31/0x32/0x33), antenna
// offsets (0x0D,0x13 and 0x0D,0x54), speed lever arm (0x0D,0x61), wheeled-vehicle constraint
// (0x0D,0x63), aiding measurement control (0x0D,0x50) — are applied to the engine as well as
// being acknowledged; legacy external headings (0x0D,0x17/0x1F) are fused as 0x13 aiding is.
// On a device link the 0x82 stream also carries the estimated calibration (odometer scale factor
// error, antenna offset correction: frontends/mip/encoder_calibration.hpp); a file
// (run --mip-out file:F) holds exactly what replay writes. The other filter-configuration and aiding commands the CV7
// documents, which the engine cannot take at run time, are NACKed "command failed" (0x04) rather
// than acknowledged and ignored (kRefused in the .cpp, issue 17).
#pragma once

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "apps/output/mip_epoch_encoder.hpp"
#include "apps/run/device_emulator.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/packet.hpp"
#include "frontends/mip/responder.hpp"

namespace navfuse::apps {

class MipDeviceEmulator final : public DeviceEmulator {
 public:
  // What the device is set to at start (config imu.mounting_rpy_deg, gnss.lever_arm_m):
  // `mounting_rpy_rad` (sensor -> vehicle) turns headings a client gives of the sensor frame into
  // the vehicle's; `gnss_lever_arm_m` is what the antenna offset correction (0x82,0x34) is
  // relative to. `device_link`: a link a client talks on, not a file.
  explicit MipDeviceEmulator(const Eigen::Vector3d& mounting_rpy_rad = Eigen::Vector3d::Zero(),
                             const Eigen::Vector3d& gnss_lever_arm_m = Eigen::Vector3d::Zero(), bool device_link = true);
  std::string_view protocol() const override { return "mip"; }
  void stream(const OutputEpoch& epoch, std::vector<std::uint8_t>& out) override;
  void receive(io::PeerId peer, std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& reply,
               CommandEffects& effects) override;

 private:
  frontends::mip::Framer& framer_for(io::PeerId peer);
  // Reads the ACK/NACK fields of packet_reply_ into acked_; true when any command was accepted.
  bool acknowledged_any();
  bool acknowledged(std::uint8_t desc_set, std::uint8_t desc) const;
  // Engine actions and aiding for the accepted commands of one packet.
  void engine_effects(const frontends::mip::PacketView& packet, CommandEffects& effects);
  void mounting_command(const frontends::mip::FieldView& field, CommandEffects& effects);
  void filter_command(const frontends::mip::FieldView& field, CommandEffects& effects);

  frontends::mip::CommandResponder responder_;
  MipEpochEncoder encoder_;
  std::map<io::PeerId, std::unique_ptr<frontends::mip::Framer>> framers_;  // one per client
  std::int64_t last_epoch_gps_ns_ = 0;  // "time of arrival" of 0x13 timebase-3 aiding
  Eigen::Matrix3d c_vs_;  // sensor -> vehicle, as last set
  Eigen::Vector3d gnss_lever_arm_m_;  // primary antenna offset in force (vehicle frame)
  bool device_link_;
  std::vector<std::uint8_t> packet_reply_;
  std::vector<Measurement> packet_aiding_;
  std::vector<std::pair<std::uint8_t, std::uint8_t>> acked_;  // (set, descriptor) of the last packet
};

}  // namespace navfuse::apps
