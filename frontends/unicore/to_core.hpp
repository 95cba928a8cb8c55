// How UM220-INS outputs become core measurements (and, in encoder.cpp, the way back). Pure
// functions of a decoded message and its resolved GPS time; the decoder holds the state (latest
// accuracy, status, position) they take as arguments.
//
// Mapping (issue #6; digest §12):
//   GYOACC      -> ImuSample (rates, sensor frame, low_rate) + WheelTicks (1 channel, cumulative)
//                  [+ VehicleSpeed when a pulse-to-metre scale is configured]
//   GYOACC-V    -> ImuSample (rates, vehicle frame, converted from right-forward-up to FRD);
//                  none while the device prints null IMU fields (not aligned, L771)
//   NAVPOS      -> GnssPosition; NAVVEL -> GnssVelocity (ECEF -> NED at the last NAVPOS). These
//                  carry the receiver's constellation mask and clock drift: the GNSS solution.
//                  Covariance from the latest NAVACC (horizontal only, see kVerticalStdPerHorizontalRms).
//   GGA         -> NavSolution (device_solution): with CFGINS mode 1 the NMEA output is the
//                  integrated INS solution (L515), FS = 6 marking dead reckoning. Position std
//                  from the latest GST.
//   NAVATT      -> NavSolution (device_solution) with attitude only.
//   SNRSTAT     -> no measurement; its state is packed into NavSolution::device_status.
#pragma once

#include <cstdint>
#include <optional>

#include "core/measurements/measurements.hpp"
#include "frontends/nmea/sentences.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {

// NAVACC reports only 2-D horizontal RMS (L1360-L1363). The per-axis horizontal std is that RMS
// over sqrt(2); the vertical std, which the device does not report, is 1.5 times the 2-D RMS: the
// GPS SPS Performance Standard's global averages (4th ed. 2008, section 3.8: 9 m horizontal,
// 15 m vertical, 95 %) give (15 / 1.96) / (9 / 1.73) = 1.47, 1.73 being the 95 % radius of a
// circular 2-D error in RMS units. The same ratio for NAVVEL's single speed accuracy (Doppler
// velocity sees the same geometry). Until 2026-11-29 it was 1.0, and the simulated UM220 log,
// whose receiver has the usual 2:1 vertical to per-axis horizontal noise, showed vertical
// position and velocity NIS of 2.0 (README, "make demo").
inline constexpr double kVerticalStdPerHorizontalRms = 1.5;
inline constexpr double kMillimetre = 1e-3;

// NavSolution::device_status packs the latest SNRSTAT, one signed byte per field:
// bits 0-7 insstatus, 8-15 odostatus, 16-23 InstallState, 24-31 mapstat (L815-L820).
std::uint32_t pack_snrstat(const Snrstat& s);
Snrstat unpack_snrstat(std::uint32_t device_status);

// GYOACC/GYOACC-V -> ImuSample; nullopt if any IMU field is null.
std::optional<ImuSample> imu_from_gyoacc(const Gyoacc& m, std::int64_t gps_ns);
// Right-forward-up (GYOACC-V axes, L797-L800) <-> forward-right-down.
Eigen::Vector3d frd_from_rfu(const Eigen::Vector3d& v);
Eigen::Vector3d rfu_from_frd(const Eigen::Vector3d& v);

// NAVPOS quality (L1289) -> fix type: 3 precise -> 3D, 2 coarse -> 2D, else none.
GnssFixType fix_from_quality(std::uint32_t quality);
std::uint32_t quality_from_fix(GnssFixType fix);

GnssPosition position_from_navpos(const Navpos& m, std::int64_t gps_ns, const Navacc* accuracy);
GnssVelocity velocity_from_navvel(const Navvel& m, std::int64_t gps_ns, double lat_rad,
                                  double lon_rad, const Navacc* accuracy);

// GGA (+ GST std, + SNRSTAT status) -> device solution.
NavSolution solution_from_gga(const nmea::Gga& m, std::int64_t gps_ns, const nmea::Gst* std_dev,
                              const Snrstat* status);
// GGA FS (L880-L882) <-> NavMode / GnssFixType.
NavMode mode_from_gga_quality(std::uint32_t quality, const Snrstat* status);
std::uint32_t gga_quality_from_solution(const NavSolution& s);

// NAVATT -> device solution with attitude; `mode` is the latest GGA mode if any.
NavSolution solution_from_navatt(const Navatt& m, std::int64_t gps_ns, std::optional<NavMode> mode,
                                 const Snrstat* status);

}  // namespace navfuse::frontends::unicore
