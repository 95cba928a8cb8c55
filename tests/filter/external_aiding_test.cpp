// External aiding (MIP 0x13 style) on closed-form streams: heading initialisation, LLH and ECEF
// positions with per-axis validity, vehicle-frame velocity, and gating of a wrong position.
#include <gtest/gtest.h>

#include <random>

#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"
#include "filter/engine.hpp"
#include "tests/filter/line_trajectory.hpp"

namespace navfuse::filter {
namespace {

const Eigen::Vector3d kRpy = Eigen::Vector3d(1.0, -2.0, -120.0) * rot::kDegToRad;

ExternalHeading heading_at(const test::LineTruth& t, double std_rad) {
  ExternalHeading h;
  h.header.time_ns = t.time_ns;
  h.header.valid = ExternalHeading::kValidHeading;
  h.heading_rad = t.rpy_rad.z();
  h.std_rad = std_rad;
  return h;
}

ExternalPosition position_at(const test::LineTruth& t, PositionFrame frame, std::uint32_t valid,
                             const Eigen::Vector3d& offset_ned_m = Eigen::Vector3d::Zero()) {
  ExternalPosition p;
  p.header.time_ns = t.time_ns;
  p.header.valid = valid;
  p.frame = frame;
  const geo::Llh llh = geo::llh_offset(t.llh, offset_ned_m);
  p.value = frame == PositionFrame::kLlh ? Eigen::Vector3d(llh.lat_rad, llh.lon_rad, llh.height_m)
                                         : geo::ecef_from_llh(llh);
  p.std_m = Eigen::Vector3d(0.5, 0.5, 0.5);
  return p;
}

TEST(ExternalAiding, HeadingThenPositionReachNavigation) {
  Engine e{FilterOptions{}};
  test::LineTrajectory traj({0.6, -1.2, 80.0}, Eigen::Vector3d::Zero(), kRpy, 200.0);
  for (int k = 0; k < 400; ++k) e.process(traj.next());  // levelled after ~1.2 s
  ASSERT_EQ(e.solution().mode, NavMode::kVerticalGyro);
  e.process(heading_at(traj.truth(), 0.5 * rot::kDegToRad));
  for (int k = 0; k < 10; ++k) e.process(traj.next());
  EXPECT_EQ(e.solution().mode, NavMode::kAhrs);
  EXPECT_NEAR(rot::wrap_pi(e.solution().rpy_rad.z() - kRpy.z()), 0.0, 0.01 * rot::kDegToRad);

  const std::uint32_t xyz = ExternalPosition::kValidX | ExternalPosition::kValidY | ExternalPosition::kValidZ;
  e.process(position_at(traj.truth(), PositionFrame::kLlh, xyz));
  for (int k = 0; k < 10; ++k) e.process(traj.next());
  EXPECT_EQ(e.solution().mode, NavMode::kNavigation);

  // ECEF positions at 1 Hz for 20 s, one of them 30 m off (gated), and one with only X valid.
  for (int s = 0; s < 20; ++s) {
    for (int k = 0; k < 200; ++k) e.process(traj.next());
    const Eigen::Vector3d off = s == 10 ? Eigen::Vector3d(30.0, 0.0, 0.0) : Eigen::Vector3d::Zero();
    e.process(position_at(traj.truth(), PositionFrame::kEcef, s == 5 ? ExternalPosition::kValidX : xyz, off));
  }
  const FilterStats& st = e.stats();
  EXPECT_EQ(st.of(MeasurementKind::kExternalPosition).used, 20u);
  EXPECT_EQ(st.of(MeasurementKind::kExternalPosition).rejected_for(RejectReason::kChi2Gate), 1u);
  const geo::Llh est{e.solution().lat_rad, e.solution().lon_rad, e.solution().height_m};
  EXPECT_LT(geo::ned_offset_m(traj.truth().llh, est).norm(), 0.5);
  EXPECT_LT(e.solution().pos_std_ned_m.head<2>().norm(), 0.5);
}

// gates.external_position (FilterOptions::aid_chi2_gate): a position 1.5 m off, against fixes of
// 0.5 m std (NIS about 1.5^2 / 0.5^2 = 9 once the filter has converged), passes the 3-D gate
// (21.11) and fails a gate of 4 set for external positions; the same gate set for another source
// leaves positions to the by-dimension gate.
TEST(ExternalAiding, AnAidsOwnGateAppliesToThatAidOnly) {
  auto gated_positions = [](GatedAid aid, double chi2) {
    FilterOptions o;
    o.initial_heading_rad = kRpy.z();
    o.aid_chi2_gate[static_cast<std::size_t>(aid)] = chi2;
    Engine e{o};
    test::LineTrajectory traj({0.6, -1.2, 80.0}, Eigen::Vector3d::Zero(), kRpy, 200.0);
    const std::uint32_t xyz = ExternalPosition::kValidX | ExternalPosition::kValidY | ExternalPosition::kValidZ;
    for (int s = 0; s < 20; ++s) {
      for (int k = 0; k < 200; ++k) e.process(traj.next());
      const Eigen::Vector3d off = s == 15 ? Eigen::Vector3d(1.5, 0.0, 0.0) : Eigen::Vector3d::Zero();
      e.process(position_at(traj.truth(), PositionFrame::kLlh, xyz, off));
    }
    EXPECT_EQ(e.solution().mode, NavMode::kNavigation);
    return e.stats().of(MeasurementKind::kExternalPosition).rejected_for(RejectReason::kChi2Gate);
  };
  EXPECT_EQ(gated_positions(GatedAid::kExternalPosition, 4.0), 1u);
  EXPECT_EQ(gated_positions(GatedAid::kExternalVelocity, 4.0), 0u);
  EXPECT_EQ(gated_positions(GatedAid::kExternalPosition, 0.0), 0u);  // 0: by dimension
}

TEST(ExternalAiding, VehicleFrameVelocityIsFused) {
  FilterOptions o;
  o.initial_heading_rad = kRpy.z();
  Engine e{o};
  test::LineTrajectory traj({0.6, -1.2, 80.0}, Eigen::Vector3d::Zero(), kRpy, 200.0);
  for (int k = 0; k < 400; ++k) e.process(traj.next());
  ExternalVelocity v;
  v.frame = VelocityFrame::kVehicle;
  v.header.valid = ExternalVelocity::kValidX | ExternalVelocity::kValidY;
  v.std_mps = Eigen::Vector3d(0.01, 0.01, -1.0);  // z invalid, so its std is not checked
  for (int s = 0; s < 10; ++s) {
    for (int k = 0; k < 20; ++k) e.process(traj.next());
    v.header.time_ns = traj.truth().time_ns;
    e.process(v);
  }
  EXPECT_EQ(e.stats().of(MeasurementKind::kExternalVelocity).used, 10u);
  EXPECT_LT(e.solution().vel_ned_mps.norm(), 0.02);
}

}  // namespace
}  // namespace navfuse::filter
