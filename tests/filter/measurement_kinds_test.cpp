// The per-kind table (filter/measurement_kinds.hpp): complete by construction, and the Engine
// follows it.
#include <gtest/gtest.h>

#include "filter/engine.hpp"
#include "filter/measurement_kinds.hpp"

namespace navfuse::filter {
namespace {

// The mechanism that makes a new MeasurementKind without a row fail to compile: the table is
// sized by kCount, so a forgotten row is value-initialised (kind kImu at its index) and
// covers_every_kind, static_assert-ed in the header, is false.
constexpr MeasurementKindTable missing_last_row() {
  MeasurementKindTable t{};
  for (std::size_t i = 0; i + 1 < kKindCount; ++i) t[i] = kMeasurementKinds[i];
  return t;
}
static_assert(!covers_every_kind(missing_last_row()), "a table without the last kind's row is rejected");
static_assert(!covers_every_kind(std::array<MeasurementKindRow, kKindCount - 1>{}),
              "a table one row short is rejected");
constexpr MeasurementKindTable fused_without_check() {
  MeasurementKindTable t = kMeasurementKinds;
  t[static_cast<std::size_t>(MeasurementKind::kGnssPosition)].check = nullptr;
  return t;
}
static_assert(!covers_every_kind(fused_without_check()), "a fused kind needs its input check");
constexpr MeasurementKindTable unfused_on_the_grid() {
  MeasurementKindTable t = kMeasurementKinds;
  t[static_cast<std::size_t>(MeasurementKind::kDeviceSolution)].when = FuseTime::kCovarianceGrid;
  return t;
}
static_assert(!covers_every_kind(unfused_on_the_grid()), "only a kind the filter fuses can wait for the grid");

// The kinds fused at the covariance grid are the ones whose models shift the state back to their
// time (filter/measurements/wheel_speed.hpp); positions, headings and the rest keep their own.
static_assert(waits_for_covariance_grid(MeasurementKind::kWheelSpeed) &&
              waits_for_covariance_grid(MeasurementKind::kVehicleSpeed) &&
              waits_for_covariance_grid(MeasurementKind::kWheelTicks));
static_assert(!waits_for_covariance_grid(MeasurementKind::kGnssPosition) &&
              !waits_for_covariance_grid(MeasurementKind::kGnssVelocity) &&
              !waits_for_covariance_grid(MeasurementKind::kGnssHeading) &&
              !waits_for_covariance_grid(MeasurementKind::kExternalPosition));

TEST(MeasurementKinds, FusedKindsAreTheOnesTheFilterHasModelsFor) {
  // DESIGN.md: device solutions are for comparison. Wheel ticks are fused since issue 17
  // (measurements/wheel_ticks.hpp), magnetometer and pressure too, when configured.
  for (MeasurementKind k : {MeasurementKind::kDeviceSolution, MeasurementKind::kCount}) {
    EXPECT_FALSE(is_fused(k)) << to_string(k);
  }
  Engine off{FilterOptions{}};
  FilterOptions on_options;
  on_options.magnetometer.enabled = true;
  on_options.baro.enabled = true;
  Engine on{on_options};
  for (MeasurementKind k : {MeasurementKind::kMagnetometer, MeasurementKind::kPressure}) {
    EXPECT_TRUE(is_fused(k)) << to_string(k);
    EXPECT_FALSE(off.fuses(k)) << to_string(k) << ": off unless configured";
    EXPECT_TRUE(on.fuses(k)) << to_string(k);
  }
  for (MeasurementKind k : {MeasurementKind::kImu, MeasurementKind::kGnssPosition, MeasurementKind::kGnssVelocity,
                            MeasurementKind::kGnssHeading, MeasurementKind::kWheelSpeed,
                            MeasurementKind::kVehicleSpeed, MeasurementKind::kWheelTicks,
                            MeasurementKind::kExternalPosition,
                            MeasurementKind::kExternalVelocity, MeasurementKind::kExternalHeading,
                            MeasurementKind::kMagnetometer, MeasurementKind::kPressure}) {
    EXPECT_TRUE(is_fused(k)) << to_string(k);
  }
  EXPECT_EQ(kind_row(MeasurementKind::kGnssHeading).name(), "gnss_heading");
}

TEST(MeasurementKinds, EngineCountsUnfusedKindsAsIgnoredAndChecksFusedOnes) {
  Engine engine{FilterOptions{}};
  engine.process(Measurement{Pressure{}});
  GnssVelocity bad;
  bad.header.valid = GnssVelocity::kValidVelocity;
  bad.vel_ned_mps.x() = std::nan("");
  engine.process(Measurement{bad});
  const FilterStats& st = engine.stats();
  EXPECT_EQ(st.of(MeasurementKind::kPressure).ignored, 1u);
  EXPECT_EQ(st.of(MeasurementKind::kGnssVelocity).ignored, 0u);
  EXPECT_EQ(st.of(MeasurementKind::kGnssVelocity).rejected[static_cast<std::size_t>(RejectReason::kNan)], 1u);
}

}  // namespace
}  // namespace navfuse::filter
