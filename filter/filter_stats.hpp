// Per-measurement-kind bookkeeping: how many were fused, ignored (a kind the filter cannot use)
// or rejected, by reason. The reason strings are what `--summary-json` reports.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "core/measurements/measurements.hpp"

namespace navfuse::filter {

enum class RejectReason : std::uint8_t {
  kNan = 0,         // NaN or infinity in a value or an uncertainty
  kNegativeStd,     // an uncertainty <= 0 on a valid axis
  kInvalid,         // no valid axis / validity bits say unusable
  kTimeBackwards,   // an IMU sample not after the previous one
  kTimeGap,         // an IMU gap beyond max_imu_gap_s: the filter restarted
  kTooLate,         // older than the state history (max_latency_s)
  kNotAligned,      // needs a mode the filter has not reached yet
  kNoFix,           // GNSS without a position fix (none, time only, receiver DR)
  kChi2Gate,        // innovation outside the chi-square gate
  kNumerical,       // singular innovation covariance
  kOverflow,        // pending-measurement buffer full
  kNoReference,     // a tick count with no earlier count of its stream to difference (first, after a gap)
  kNoScale,         // tick counts while no tick-to-metre scale is configured (wheel.m_per_tick)
  kBaselineMismatch,  // dual-antenna heading after its baseline was found off the course over ground
  kMagneticDisturbance,  // a magnetometer reading whose strength is not the earth's field
  kNoDeclination,     // magnetic heading with no declination configured or modelled
  kGnssJump,          // a GNSS fix displaced by a step away from the inertial track (multipath, wrong fix)
  kCount,
};
std::string_view to_string(RejectReason reason);

// Innovations of the updates tried for one kind (accepted or gated), for consistency checks: a
// consistent filter has a mean NIS per dimension near 1.
struct InnovationStats {
  std::uint64_t count = 0;
  std::uint64_t above_gate = 0;
  double nis_sum = 0.0;
  double nis_per_dim_sum = 0.0;
  double mean_nis() const { return count ? nis_sum / static_cast<double>(count) : 0.0; }
  double mean_nis_per_dim() const { return count ? nis_per_dim_sum / static_cast<double>(count) : 0.0; }
  double fraction_above_gate() const {
    return count ? static_cast<double>(above_gate) / static_cast<double>(count) : 0.0;
  }
  // One update tried: its NIS over `rows` dimensions, and whether the gate refused it.
  void add(double nis, int rows, bool gated) {
    ++count;
    nis_sum += nis;
    nis_per_dim_sum += nis / rows;
    if (gated) ++above_gate;
  }
};

struct KindStats {
  InnovationStats innovation;
  std::uint64_t used = 0;
  std::uint64_t ignored = 0;
  std::array<std::uint64_t, static_cast<std::size_t>(RejectReason::kCount)> rejected{};

  std::uint64_t rejected_total() const;
  std::uint64_t rejected_for(RejectReason r) const { return rejected[static_cast<std::size_t>(r)]; }
};

struct FilterStats {
  std::array<KindStats, static_cast<std::size_t>(MeasurementKind::kCount)> kinds{};
  std::uint64_t resets = 0;          // restarts to Init (divergence, command, IMU gap)
  std::uint64_t gnss_recoveries = 0;  // re-anchored to GNSS after sustained rejection
  std::uint64_t replays = 0;          // late measurements fused by re-propagation
  std::uint64_t zupts = 0;           // zero-velocity updates applied
  std::uint64_t accel_tilt_updates = 0;  // gravity-reference updates applied (control/tilt_control.hpp)
  std::uint64_t nhc_updates = 0;     // non-holonomic constraint updates applied
  // The constraint's innovations (tried, accepted or gated): far above 1 per dimension says the
  // constraint point is not where the vehicle does not slip (nhc.lever_arm_m).
  InnovationStats nhc_innovation;
  std::uint64_t covariance_inflations = 0;  // over-confidence repaired (innovation_adaptation)
  std::uint64_t output_jumps_blended = 0;   // position corrections the output took gradually (output_blend)
  double process_noise_scale = 1.0;         // current adaptive multiplier on the random walks
  double max_process_noise_scale = 1.0;     // largest it reached
  // Largest multiplier put on the GNSS position / velocity variances as reported
  // (control/measurement_noise_adaptation.hpp).
  double max_gnss_position_noise_scale = 1.0;
  double max_gnss_velocity_noise_scale = 1.0;

  const KindStats& of(MeasurementKind k) const { return kinds[static_cast<std::size_t>(k)]; }
  KindStats& of(MeasurementKind k) { return kinds[static_cast<std::size_t>(k)]; }
};

}  // namespace navfuse::filter
