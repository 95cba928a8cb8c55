// Common group (group bit 0; ICD Table 2.3, L761-784; digest §5.1): copies of other groups'
// types with identical layouts, stored into the referenced groups' fields.
#pragma once

#include "frontends/vectornav/binary_message.hpp"
#include "frontends/vectornav/field_io.hpp"
#include "frontends/vectornav/group_attitude.hpp"
#include "frontends/vectornav/group_imu.hpp"
#include "frontends/vectornav/group_ins.hpp"
#include "frontends/vectornav/group_time.hpp"

namespace navfuse::frontends::vectornav {

template <class Io>
void visit_common_type(unsigned bit, Io& io, BinaryMessage& m) {
  switch (bit) {
    case common_type::kTimeStartup: visit_time_type(time_type::kTimeStartup, io, m.time); break;
    case common_type::kTimeGps: visit_time_type(time_type::kTimeGps, io, m.time); break;
    case common_type::kTimeSyncIn: visit_time_type(time_type::kTimeSyncIn, io, m.time); break;
    case common_type::kYpr: visit_attitude_type(attitude_type::kYpr, io, m.attitude); break;
    case common_type::kQuaternion: visit_attitude_type(attitude_type::kQuaternion, io, m.attitude); break;
    case common_type::kAngularRate: visit_imu_type(imu_type::kAngularRate, io, m.imu); break;
    case common_type::kPosLla: visit_ins_type(ins_type::kPosLla, io, m.ins); break;
    case common_type::kVelNed: visit_ins_type(ins_type::kVelNed, io, m.ins); break;
    case common_type::kAccel: visit_imu_type(imu_type::kAccel, io, m.imu); break;
    case common_type::kImu:  // UncompAccel then UncompGyro (L774)
      visit_imu_type(imu_type::kUncompAccel, io, m.imu);
      visit_imu_type(imu_type::kUncompGyro, io, m.imu);
      break;
    case common_type::kMagPres:  // Mag, Temperature, Pressure in that order (L775)
      visit_imu_type(imu_type::kMag, io, m.imu);
      visit_imu_type(imu_type::kTemperature, io, m.imu);
      visit_imu_type(imu_type::kPressure, io, m.imu);
      break;
    case common_type::kDeltas:  // DeltaTheta then DeltaVel (L776)
      visit_imu_type(imu_type::kDeltaTheta, io, m.imu);
      visit_imu_type(imu_type::kDeltaVel, io, m.imu);
      break;
    case common_type::kInsStatus: visit_ins_type(ins_type::kInsStatus, io, m.ins); break;
    case common_type::kSyncInCnt: visit_time_type(time_type::kSyncInCnt, io, m.time); break;
    case common_type::kTimeGpsPps: visit_time_type(time_type::kTimeGpsPps, io, m.time); break;
    default: break;
  }
}

}  // namespace navfuse::frontends::vectornav
