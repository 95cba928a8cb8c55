// What a command received on an output link (FusionEngine ResetRequest / SetConfig, MIP filter
// commands) asks of the filter. Output threads queue these; the filter thread, the only one that
// touches the engine, applies them between measurements.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "apps/run/bounded_queue.hpp"
#include "core/measurements/measurements.hpp"

namespace navfuse::apps {

struct EngineAction {
  enum class Kind : std::uint8_t {
    kReset,          // reset_mask: filter::Engine::kReset* bits
    kGnssLeverArm,   // vector (vehicle FRD, m), antenna 0 primary / 1 secondary
    kMounting,       // vector: sensor -> vehicle roll, pitch, yaw (rad)
    kWheelLeverArm,  // vector (vehicle FRD, m)
    kNonholonomic,   // enable: the wheeled-vehicle constraint
    kAiding,         // enable: aiding of `aiding` (filter::Engine::set_aiding)
    kInitialHeading, // heading_rad (filter::Engine::set_initial_heading)
  };
  Kind kind = Kind::kReset;
  std::uint32_t reset_mask = 0;
  Eigen::Vector3d vector = Eigen::Vector3d::Zero();
  int antenna = 0;
  bool enable = false;
  MeasurementKind aiding = MeasurementKind::kImu;
  double heading_rad = 0.0;

  static EngineAction reset(std::uint32_t mask) {
    EngineAction a;
    a.kind = Kind::kReset;
    a.reset_mask = mask;
    return a;
  }
  static EngineAction initial_heading(double heading_rad) {
    EngineAction a;
    a.kind = Kind::kInitialHeading;
    a.heading_rad = heading_rad;
    return a;
  }
  static EngineAction switch_to(Kind kind, bool enable, MeasurementKind aiding = MeasurementKind::kImu) {
    EngineAction a;
    a.kind = kind;
    a.enable = enable;
    a.aiding = aiding;
    return a;
  }
  static EngineAction with_vector(Kind kind, const Eigen::Vector3d& v, int antenna = 0) {
    EngineAction a;
    a.kind = kind;
    a.vector = v;
    a.antenna = antenna;
    return a;
  }
};

using EngineActionQueue = BoundedQueue<EngineAction>;

}  // namespace navfuse::apps
