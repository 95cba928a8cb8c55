// The host side of FusionEngine device commands for `navfuse run --configure-device` (issue 17):
// the installation geometry from the config as SetConfig messages (spec §3.1.6, L939-1037),
// each read back with GetConfig (ACTIVE, L1309-1332) and its ConfigResponse (L1594-1622)
// compared with what was set, and the reading of refusals in the replies.
//
// What is set: GNSS Lever Arm (0x12) = gnss.lever_arm_m, GNSS Aux Lever Arm (0x18) =
// gnss.secondary_lever_arm_m when the config has a second antenna, and Device Lever Arm (0x10)
// = 0. Every navfuse lever arm is measured from the IMU (DESIGN.md: "from the vehicle reference
// point, the IMU origin"), while a FusionEngine device measures them from its body-frame origin
// and places its IMU there by the Device Lever Arm: only with that at zero do the two agree.
// Frames: config FRD, Point3f FLU body (spec L635-653): y and z change sign; the device's body
// is the vehicle, so no mounting enters. Not set: the Output Lever Arm (0x13, where the device
// reports its own pose, the user's choice; navfuse fuses the device's sensor data, not that
// pose) and the Device Orientation (0x11, only 90 deg steps; it would rotate the IMU data navfuse
// rotates by imu.mounting_rpy_deg again).
//
// Output rates: IMUOutput, Pose and GNSSInfo, what navfuse decodes from a FusionEngine device,
// are set to On Change, the spec's "max rate" (example L1490-1497: every new IMU sample and
// solution), with SetMessageRate (L1419-1524) on the interface the command arrives on (Current,
// 0xFE, L576-602), and read back with GetMessageRate / MessageRateResponse (L1528-1552,
// L1655-1690). Settings and rates are applied, not saved (no SaveConfig, no APPLY_AND_SAVE), as
// for the other devices: the set-up is sent again whenever the link re-opens.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/config/config.hpp"
#include "frontends/common/install_geometry.hpp"
#include "frontends/common/setup_step.hpp"
#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/messages_control.hpp"
#include "frontends/fusionengine/writer.hpp"

namespace navfuse::frontends::fusionengine {

// SetConfig (apply, not save) and GetConfig (ACTIVE) of a Point3f setting, framed by `writer`.
std::vector<std::uint8_t> set_point_config(FusionEngineWriter& writer, ConfigType type, const Point3f& value);
std::vector<std::uint8_t> get_config(FusionEngineWriter& writer, ConfigType type);

// SetMessageRate / GetMessageRate (ACTIVE) of one FusionEngine message on `iface`.
std::vector<std::uint8_t> set_message_rate(FusionEngineWriter& writer, MessageType message, MessageRate rate,
                                           const InterfaceId& iface);
std::vector<std::uint8_t> get_message_rate(FusionEngineWriter& writer, MessageType message, const InterfaceId& iface);
// The check of a GetMessageRate's answer: "" when a MessageRateResponse says OK and gives
// `message` the configured rate `sent`.
std::string verify_message_rate(std::span<const std::uint8_t> reply_bytes, MessageType message, MessageRate sent);

// The check of a GetConfig's answer: "" when a ConfigResponse for `type` says OK and holds `sent`.
std::string verify_point_config(std::span<const std::uint8_t> reply_bytes, ConfigType type, const Point3f& sent);

// SetConfig and GetConfig with its check for each setting above, then the output rates.
std::vector<SetupStep> fusion_setup_steps(const config::Config& config);

// The first CommandResponse or ConfigResponse in `reply_bytes` whose Response is not OK (spec
// L1579-1590), as "FusionEngine <message> response <code> (<name>)"; "" when none.
std::string find_refusal(std::span<const std::uint8_t> reply_bytes);

}  // namespace navfuse::frontends::fusionengine
