// The installation geometry of `navfuse run --configure-device` for a VN-300 (issue 17): the
// GNSS A antenna offset (Reg 57, ICD §3.7.2 L3844-3868) and the compass baseline with its
// uncertainty (Reg 93, L4255-4287) written from the config, each read back ($VNRRG) and compared.
//
// Frame: both registers are in the VN-300 body frame, the frame its binary outputs are in (the
// sensor frame turned by the reference frame rotation, Reg 26, L3466-3501). navfuse turns that
// frame into the vehicle by imu.mounting_rpy_deg, so the config's vehicle-frame lever arms are
// sent as C_vs^T r (frontends/common/install_geometry.hpp), right whatever Reg 26 holds.
//
// Reg 26 itself is not written: it would turn the IMU data navfuse already rotates by its own
// mounting (rotating it twice), and it is a static register that takes effect only after Write
// Settings and a reset (L3470), which would drop the link's unsaved set-up.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/config/config.hpp"
#include "frontends/common/install_geometry.hpp"
#include "frontends/common/setup_step.hpp"
#include "frontends/vectornav/commands.hpp"

namespace navfuse::frontends::vectornav::cmd {

// The VN-300 prints these registers with 3 decimals (Reg 93's uncertainty with 4, L3849,
// L4258): a value read back within half a millimetre plus the f32 rounding is the value sent.
inline constexpr double kReadBackToleranceM = 1e-3;

// fusion_setup_commands()'s options with the config's antenna offset and, when the config has a
// second antenna, its baseline B - A (Reg 93 uncertainty: the register's default, 0.0254 m).
FusionSetup fusion_setup_from_config(const config::Config& config);

// The first "$VNRRG,<id>,..." reply in `reply_bytes` (any other output around it is skipped).
std::optional<Reply> find_register_reply(std::span<const std::uint8_t> reply_bytes, int register_id);
// Read-back checks (SetupStep::verify): "" when the reply holds what was sent.
std::string verify_antenna_offset(std::span<const std::uint8_t> reply_bytes, const Eigen::Vector3d& sent_m);
std::string verify_compass_baseline(std::span<const std::uint8_t> reply_bytes, const CompassBaseline& sent);

// fusion_setup_commands(fusion_setup_from_config(config)), then a read of Reg 57 (and Reg 93)
// with its check, before output is resumed.
std::vector<SetupStep> fusion_setup_steps(const config::Config& config);

}  // namespace navfuse::frontends::vectornav::cmd
