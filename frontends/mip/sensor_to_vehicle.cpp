#include "frontends/mip/sensor_to_vehicle.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "core/bytes/byte_reader.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::frontends::mip {
namespace {

constexpr double kRotationTolerance = 1e-3;

}  // namespace

std::optional<Eigen::Matrix3d> sensor_to_vehicle_dcm(std::uint8_t desc, std::span<const std::uint8_t> params) {
  bytes::BeReader r(params);
  Eigen::Matrix3d c;
  switch (desc) {
    case kSensorToVehicleEuler: {
      Eigen::Vector3d rpy;
      for (int i = 0; i < 3; ++i) rpy[i] = r.f32();
      if (!r.ok() || !rpy.allFinite()) return std::nullopt;
      return rot::dcm_from_rpy(rpy);
    }
    case kSensorToVehicleQuaternion: {
      Eigen::Vector4d wxyz;
      for (int i = 0; i < 4; ++i) wxyz[i] = r.f32();
      if (!r.ok() || !wxyz.allFinite() || std::abs(wxyz.norm() - 1.0) > kRotationTolerance) return std::nullopt;
      const Eigen::Quaterniond q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
      c = q.normalized().toRotationMatrix().transpose();
      return c;
    }
    case kSensorToVehicleDcm: {
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) c(row, col) = r.f32();
      if (!r.ok() || !c.allFinite()) return std::nullopt;
      if ((c * c.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > kRotationTolerance ||
          c.determinant() < 0) {
        return std::nullopt;
      }
      return c;
    }
    default: return std::nullopt;
  }
}

}  // namespace navfuse::frontends::mip
