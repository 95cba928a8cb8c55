// Sensor set 0x80 -> ImuSample, Magnetometer, Pressure, VehicleSpeed (digest §4.1).
#include "frontends/mip/decoder.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/mip/decoder_detail.hpp"
#include "frontends/mip/units.hpp"

namespace navfuse::frontends::mip {

using namespace detail;

void MipDecoder::decode_sensor(const PacketView& p, DecodeSink& sink) {
  TimeFields tf;
  bool error = false;
  const std::uint8_t* accel = nullptr;
  const std::uint8_t* gyro = nullptr;
  const std::uint8_t* dtheta = nullptr;
  const std::uint8_t* dvel = nullptr;
  const std::uint8_t* mag = nullptr;
  const std::uint8_t* pressure = nullptr;
  const std::uint8_t* odometer = nullptr;
  std::uint16_t overrange = 0;
  FieldWalker walk(p.payload);
  FieldView f;
  auto need = [&](std::size_t n) {
    if (f.data.size() >= n) return f.data.data();
    error = true;
    return static_cast<const std::uint8_t*>(nullptr);
  };
  while (walk.next(f)) {
    switch (f.desc) {
      case sensor::kScaledAccel: accel = need(kVec3fSize); break;
      case sensor::kScaledGyro: gyro = need(kVec3fSize); break;
      case sensor::kDeltaTheta: dtheta = need(kVec3fSize); break;
      case sensor::kDeltaVelocity: dvel = need(kVec3fSize); break;
      case sensor::kScaledMag: mag = need(kVec3fSize); break;
      case sensor::kScaledPressure: pressure = need(kPressureSize); break;
      case sensor::kOdometer: odometer = need(kOdometerSize); break;
      case sensor::kOverrange:
        if (const auto* d = need(kOverrangeSize)) overrange = be16(d);
        break;
      case sensor::kGpsTimestamp:
        // Legacy GPS timestamp: tow_valid (bit 3) and week_number_valid (bit 4) (L6490-6496).
        if (const auto* d = need(kGpsTimeSize)) {
          if ((be16(d + kTimeValidOffset) & sensor::kLegacyTimeValid) == sensor::kLegacyTimeValid && !tf.gps &&
              std::isfinite(f64(d))) {
            tf.gps = true;
            tf.gps_ns = gps_ns(d);
          }
        }
        break;
      default: take_time(f, tf, error); break;
    }
  }
  PacketTime t;
  resolve(tf, clock_, last_time_ns_[p.desc_set], last_time_source_[p.desc_set], t.ns, t.source, t.own);
  MeasurementHeader h;
  h.time_ns = t.ns;
  h.time_source = t.source;

  if ((dtheta && dvel) || accel || gyro) {
    ImuSample m;
    m.header = h;
    m.frame = SensorFrame::kVehicle;  // 0x80 vectors are in the vehicle frame (L6393, L2485)
    if (dtheta && dvel) {
      m.quantity = ImuQuantity::kIncrements;
      m.gyro = v3f(dtheta);
      m.accel = v3f(dvel) * kGravity_mps2;  // g*s -> m/s (errata E35)
      m.header.valid = ImuSample::kValidGyro | ImuSample::kValidAccel;
      m.dt_s = tf.dt_ns >= 0 ? time::seconds(tf.dt_ns) : 0.0;
    } else {
      m.quantity = ImuQuantity::kRates;
      if (gyro) {
        m.gyro = v3f(gyro);
        m.header.valid |= ImuSample::kValidGyro;
      }
      if (accel) {
        m.accel = v3f(accel) * kGravity_mps2;  // g -> m/s^2
        m.header.valid |= ImuSample::kValidAccel;
      }
      m.dt_s = tf.dt_ns >= 0 ? time::seconds(tf.dt_ns) : 0.0;
    }
    if (overrange & sensor::kOverAccelX) m.saturation |= ImuSample::kSatAccelX;
    if (overrange & sensor::kOverAccelY) m.saturation |= ImuSample::kSatAccelY;
    if (overrange & sensor::kOverAccelZ) m.saturation |= ImuSample::kSatAccelZ;
    if (overrange & sensor::kOverGyroX) m.saturation |= ImuSample::kSatGyroX;
    if (overrange & sensor::kOverGyroY) m.saturation |= ImuSample::kSatGyroY;
    if (overrange & sensor::kOverGyroZ) m.saturation |= ImuSample::kSatGyroZ;
    if (m.gyro.allFinite() && m.accel.allFinite()) sink.on_measurement(m);
    else error = true;  // NaN on the wire (e.g. the doc's 0x7FE5BF7F, L3957): never reaches the filter
  }
  if (mag) {
    Magnetometer m;
    m.header = h;
    m.header.valid = Magnetometer::kValidField;
    m.frame = SensorFrame::kVehicle;
    m.field_gauss = v3f(mag);
    if (m.field_gauss.allFinite()) sink.on_measurement(m);
    else error = true;
  }
  if (pressure) {
    Pressure m;
    m.header = h;
    m.header.valid = Pressure::kValidPressure;
    m.pressure_pa = f32(pressure) * kMbarToPa;
    if (std::isfinite(m.pressure_pa)) sink.on_measurement(m);
    else error = true;
  }
  if (odometer && (be16(odometer + kOdoValidOffset) & 1u)) {  // bit0: odometer configured (L6559)
    VehicleSpeed m;
    m.header = h;
    m.header.valid = VehicleSpeed::kValidSpeed;
    m.speed_mps = f32(odometer);
    m.is_signed = true;  // "can be negative for quadrature encoders" (L6553)
    m.speed_std_mps = f32(odometer + kOdoStdOffset);
    if (std::isfinite(m.speed_mps) && std::isfinite(m.speed_std_mps)) sink.on_measurement(m);
    else error = true;
  }
  if (error || walk.malformed()) ++framer_.counters().decode_errors;
}

}  // namespace navfuse::frontends::mip
