// What the filter does with each MeasurementKind: one row per kind, in kind order (name, fused or
// not, input check, fuse function). Adding a kind to core/measurements without a row here fails
// to compile (the static_assert below), so the Engine, the statistics and the apps' time-base gate
// (through is_fused) cannot disagree on what is fused.
//
// Deliberately light (no filter state types): apps include it for is_fused().
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "core/measurements/measurements.hpp"
#include "filter/filter_stats.hpp"

namespace navfuse::filter {

struct FilterCore;
struct FilterOptions;
struct FuseResult;

using InputCheck = std::optional<RejectReason> (*)(const Measurement& m);
using FuseFunction = FuseResult (*)(FilterCore& core, const FilterOptions& o, const Measurement& m,
                                    double shift_s);

// The table's entry points for kind K: the typed input check (input_checks.hpp) and fuse function
// (filter/control/) applied to the variant's alternative K. Defined and instantiated in
// measurement_kinds.cpp for exactly the kinds whose rows name them (a missing one fails to link).
template <MeasurementKind K>
std::optional<RejectReason> check_kind(const Measurement& m);
template <MeasurementKind K>
FuseResult fuse_kind(FilterCore& core, const FilterOptions& o, const Measurement& m, double shift_s);

// When the Engine fuses a measurement of the kind (engine.hpp):
//   kOwnTime         at the IMU sample nearest its timestamp, the covariance brought up to that
//                    sample first (an extra covariance step when it falls between grid points);
//   kCovarianceGrid  at the end of the covariance step its timestamp falls in (the state at most
//                    FilterOptions::covariance_interval_s later), its time shift modelled: for
//                    streams at 50-100 Hz (wheel and vehicle speed, CAN odometry), which would
//                    otherwise cost a covariance step each (a 50 Hz wheel log tripled the steps
//                    of the 20 Hz grid: 30,596 against 10,372 on drive_9min).
enum class FuseTime : unsigned char { kOwnTime, kCovarianceGrid };

struct MeasurementKindRow {
  MeasurementKind kind;
  bool fused;          // false: counted as "ignored" and dropped before any check
  InputCheck check;    // NaN / impossible values / std <= 0; nullptr exactly when not fused
  FuseFunction fuse;   // nullptr when not fused, and for the IMU, which drives the strapdown
  FuseTime when = FuseTime::kOwnTime;  // kCovarianceGrid only where the model shifts in time
  std::string_view name() const { return to_string(kind); }  // core's name, the stats key
};

inline constexpr std::size_t kKindCount = static_cast<std::size_t>(MeasurementKind::kCount);
using MeasurementKindTable = std::array<MeasurementKindRow, kKindCount>;

inline constexpr MeasurementKindTable kMeasurementKinds{{
    {MeasurementKind::kImu, true, &check_kind<MeasurementKind::kImu>, nullptr},
    {MeasurementKind::kGnssPosition, true, &check_kind<MeasurementKind::kGnssPosition>,
     &fuse_kind<MeasurementKind::kGnssPosition>},
    {MeasurementKind::kGnssVelocity, true, &check_kind<MeasurementKind::kGnssVelocity>,
     &fuse_kind<MeasurementKind::kGnssVelocity>},
    {MeasurementKind::kGnssHeading, true, &check_kind<MeasurementKind::kGnssHeading>,
     &fuse_kind<MeasurementKind::kGnssHeading>},
    {MeasurementKind::kWheelSpeed, true, &check_kind<MeasurementKind::kWheelSpeed>,
     &fuse_kind<MeasurementKind::kWheelSpeed>, FuseTime::kCovarianceGrid},
    {MeasurementKind::kVehicleSpeed, true, &check_kind<MeasurementKind::kVehicleSpeed>,
     &fuse_kind<MeasurementKind::kVehicleSpeed>, FuseTime::kCovarianceGrid},
    {MeasurementKind::kWheelTicks, true, &check_kind<MeasurementKind::kWheelTicks>,
     &fuse_kind<MeasurementKind::kWheelTicks>, FuseTime::kCovarianceGrid},
    {MeasurementKind::kExternalPosition, true, &check_kind<MeasurementKind::kExternalPosition>,
     &fuse_kind<MeasurementKind::kExternalPosition>},
    {MeasurementKind::kExternalVelocity, true, &check_kind<MeasurementKind::kExternalVelocity>,
     &fuse_kind<MeasurementKind::kExternalVelocity>},
    {MeasurementKind::kExternalHeading, true, &check_kind<MeasurementKind::kExternalHeading>,
     &fuse_kind<MeasurementKind::kExternalHeading>},
    // A device's own solution is for comparison (bench), never an input to ours.
    {MeasurementKind::kDeviceSolution, false, nullptr, nullptr},
    // Fused only when the configuration switches them on (FilterOptions::fuses).
    {MeasurementKind::kMagnetometer, true, &check_kind<MeasurementKind::kMagnetometer>,
     &fuse_kind<MeasurementKind::kMagnetometer>},
    {MeasurementKind::kPressure, true, &check_kind<MeasurementKind::kPressure>,
     &fuse_kind<MeasurementKind::kPressure>},
}};

// True when `table` has one row per kind, row i for kind i, and its columns agree with `fused`.
// An omitted row is value-initialised (kind kImu, not fused), so it fails the order check.
template <std::size_t N>
constexpr bool covers_every_kind(const std::array<MeasurementKindRow, N>& table) {
  if (N != kKindCount) return false;
  for (std::size_t i = 0; i < N; ++i) {
    const MeasurementKindRow& row = table[i];
    if (static_cast<std::size_t>(row.kind) != i) return false;
    if (row.fused != (row.check != nullptr)) return false;
    const bool drives_strapdown = row.kind == MeasurementKind::kImu;
    if ((row.fuse != nullptr) != (row.fused && !drives_strapdown)) return false;
    if (row.when == FuseTime::kCovarianceGrid && row.fuse == nullptr) return false;
  }
  return true;
}
static_assert(covers_every_kind(kMeasurementKinds),
              "every MeasurementKind needs its row in kMeasurementKinds, in kind order");

constexpr const MeasurementKindRow& kind_row(MeasurementKind kind) {
  return kMeasurementKinds[static_cast<std::size_t>(kind)];
}

constexpr bool waits_for_covariance_grid(MeasurementKind kind) {
  return kind_row(kind).when == FuseTime::kCovarianceGrid;
}

// Whether the filter uses measurements of this kind (the IMU included); the rest are counted as
// ignored. kCount (not a kind) is not fused.
constexpr bool is_fused(MeasurementKind kind) {
  return static_cast<std::size_t>(kind) < kKindCount && kind_row(kind).fused;
}

}  // namespace navfuse::filter
