// The installation geometry of `navfuse run --configure-device` for a CV7 (issue 17): each GNSS
// antenna's lever arm (0x0D,0x54 GNSS Multi-Antenna Offset Control, receiver 1 and, when the
// config has a second antenna, 2; digest §6.9, L8617) and the speed-measurement lever arm
// (0x0D,0x61, L8688) written from the config, each read back (function selector 0x02, digest
// §2.6) and the response fields (0xD4 / 0xE1: key, Vector3f) compared with what was written.
//
// 0x0D,0x13 is not used: the CV7 documents it for GNSS data given by NMEA input only (L1163,
// L8279); its internal receivers take 0x0D,0x54.
//
// Frame: the CV7's offsets are in its vehicle frame, the frame it streams 0x80 in (the sensor
// frame turned by its sensor-to-vehicle transform, digest §4.1, L2485). navfuse turns that frame
// into its vehicle by imu.mounting_rpy_deg, so the config's lever arms are sent as C_vs^T r
// (frontends/common/install_geometry.hpp). The sensor-to-vehicle transform (0x0C,0x31) itself is not
// written: the device would then rotate the 0x80 IMU data that navfuse rotates by its own
// mounting again (DESIGN.md conventions), and it resets the CV7's filters (digest §1).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/config/config.hpp"
#include "frontends/common/install_geometry.hpp"
#include "frontends/common/setup_step.hpp"
#include "frontends/mip/commands.hpp"

namespace navfuse::frontends::mip {

// Checks the reply to a Read of a (desc_set, desc) setting whose response is one key byte and a
// Vector3f (0xD4, 0xE1): "" when the device ACKed and the vector equals `sent_m` (f32 as written).
std::string verify_vector_setting(std::span<const std::uint8_t> reply_bytes, std::uint8_t desc_set, std::uint8_t desc,
                                  std::uint8_t key, const Eigen::Vector3d& sent_m, std::string_view setting);

// cv7_setup_sequence(), then the geometry writes and their read-backs, before the device resumes.
std::vector<SetupStep> cv7_setup_steps(const config::Config& config);

}  // namespace navfuse::frontends::mip
