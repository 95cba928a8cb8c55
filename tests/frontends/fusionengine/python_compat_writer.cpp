// Writes a FusionEngine stream of every message navfuse outputs (and every command/response it
// exchanges) with known values, plus a JSON list of the values Point One's Python client must
// read back (attribute names are the client's). Used by python_compat_check.py.
//   usage: navfuse_fe_python_writer STREAM.p1log EXPECTED.json
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "frontends/fusionengine/config_types.hpp"
#include "frontends/fusionengine/writer.hpp"

using namespace navfuse::frontends::fusionengine;

namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}
template <class A>
std::string list(const A& a) {
  std::string s = "[";
  for (std::size_t i = 0; i < a.size(); ++i) s += (i ? ", " : "") + num(static_cast<double>(a[i]));
  return s + "]";
}
double ts(const Timestamp& t) { return t.seconds + t.fraction_ns * 1e-9; }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s STREAM EXPECTED_JSON\n", argv[0]);
    return 2;
  }
  FusionEngineWriter w;
  std::vector<std::uint8_t> bytes;
  std::vector<std::string> expected;
  auto add = [&](auto msg, std::string fields) {
    w.append(msg, bytes);
    expected.push_back("{\"type\": " + std::to_string(to_u16(decltype(msg)::kType)) + ", \"fields\": {" + fields + "}}");
  };
  const Timestamp p1{1'400'000'000, 250'000'000};

  PoseMessage pose;
  pose.p1_time = p1;
  pose.gps_time = p1;
  pose.solution_type = 4;
  pose.flags = 1;
  pose.undulation_cm = -3215;
  pose.lla_deg = {37.5, -122.25, 12.75};
  pose.position_std_enu_m = {0.5f, 0.25f, 1.5f};
  pose.ypr_deg = {45.0, -10.0, 5.0};
  pose.ypr_std_deg = {0.5f, 0.125f, 0.25f};
  pose.velocity_body_mps = {10.0, -0.5, 0.25};
  pose.velocity_std_body_mps = {0.125f, 0.25f, 0.5f};
  pose.aggregate_protection_level_m = 3.5f;
  pose.horizontal_protection_level_m = 2.5f;
  pose.vertical_protection_level_m = 1.5f;
  add(pose, "\"p1_time\": " + num(ts(p1)) + ", \"gps_time\": " + num(ts(p1)) +
                ", \"solution_type\": 4, \"flags\": 1, \"undulation_m\": -32.15, \"lla_deg\": " + list(pose.lla_deg) +
                ", \"position_std_enu_m\": " + list(pose.position_std_enu_m) + ", \"ypr_deg\": " + list(pose.ypr_deg) +
                ", \"ypr_std_deg\": " + list(pose.ypr_std_deg) + ", \"velocity_body_mps\": " +
                list(pose.velocity_body_mps) + ", \"velocity_std_body_mps\": " + list(pose.velocity_std_body_mps) +
                ", \"aggregate_protection_level_m\": 3.5");

  PoseAuxMessage aux;
  aux.p1_time = p1;
  aux.position_std_body_m = {0.25f, 0.5f, 1.0f};
  aux.position_cov_enu_m2 = {1, 0.5, 0, 0.5, 2, 0, 0, 0, 3};
  aux.attitude_quaternion = {0.0, 0.0, 0.38268343236508978, 0.92387953251128674};
  aux.velocity_enu_mps = {1.0, 2.0, -0.5};
  aux.velocity_std_enu_mps = {0.25f, 0.25f, 0.5f};
  add(aux, "\"p1_time\": " + num(ts(p1)) + ", \"position_std_body_m\": " + list(aux.position_std_body_m) +
               ", \"position_cov_enu_m2\": " + list(aux.position_cov_enu_m2) + ", \"attitude_quaternion\": " +
               list(aux.attitude_quaternion) + ", \"velocity_enu_mps\": " + list(aux.velocity_enu_mps) +
               ", \"velocity_std_enu_mps\": " + list(aux.velocity_std_enu_mps));

  GnssInfoMessage info;
  info.p1_time = p1;
  info.gps_time = p1;
  info.leap_second_s = 18;
  info.num_svs = 23;
  info.corrections_age_ds = 15;
  info.baseline_distance_dam = 12;
  info.reference_station_id = 4321;
  info.gdop = 1.5f;
  info.pdop = 1.25f;
  info.hdop = 0.75f;
  info.vdop = 1.0f;
  info.gps_time_std_s = 1e-8f;
  add(info, "\"leap_second\": 18, \"num_svs\": 23, \"corrections_age_sec\": 1.5, \"baseline_distance_m\": 120, "
            "\"reference_station_id\": 4321, \"gdop\": 1.5, \"pdop\": 1.25, \"hdop\": 0.75, \"vdop\": 1.0");

  CalibrationStatusMessage cal;
  cal.p1_time = p1;
  cal.calibration_stage = 0xFF;
  cal.ypr_deg = {1.5f, -0.5f, 0.25f};
  cal.ypr_std_deg = {0.125f, 0.0625f, 0.0625f};
  cal.travel_distance_m = 1234.5f;
  cal.state_verified = 1;
  cal.gyro_bias_half_percent = 200;
  cal.accel_bias_half_percent = 150;
  cal.mounting_half_percent = 101;
  cal.min_travel_distance_m = 1000.0f;
  cal.max_ypr_std_deg = {2.0f, 1.0f, 1.0f};
  add(cal, "\"calibration_stage\": 255, \"ypr_deg\": " + list(cal.ypr_deg) + ", \"ypr_std_dev_deg\": " +
               list(cal.ypr_std_deg) + ", \"travel_distance_m\": 1234.5, \"state_verified\": 1, "
               "\"gyro_bias_percent_complete\": 100.0, \"accel_bias_percent_complete\": 75.0, "
               "\"mounting_angle_percent_complete\": 50.5, \"min_travel_distance_m\": 1000.0, "
               "\"mounting_angle_max_std_dev_deg\": " + list(cal.max_ypr_std_deg));

  ImuOutputMessage imu;
  imu.p1_time = p1;
  imu.accel_mps2 = {0.125, -0.25, 9.80665};
  imu.accel_std_mps2 = {0.01, 0.02, 0.03};
  imu.gyro_rps = {0.001, -0.002, 0.5};
  imu.gyro_std_rps = {1e-4, 2e-4, 3e-4};
  add(imu, "\"p1_time\": " + num(ts(p1)) + ", \"accel_mps2\": " + list(imu.accel_mps2) + ", \"accel_std_mps2\": " +
               list(imu.accel_std_mps2) + ", \"gyro_rps\": " + list(imu.gyro_rps) + ", \"gyro_std_rps\": " +
               list(imu.gyro_std_rps));

  VehicleSpeedOutputMessage vs;
  vs.p1_time = p1;
  vs.data_source = 3;
  vs.gear = 2;
  vs.flags = 1;
  vs.speed_mps = -2.5f;
  add(vs, "\"data_source\": 3, \"gear\": 2, \"flags\": 1, \"vehicle_speed_mps\": -2.5");

  GnssAttitudeOutputMessage att;
  att.details.measurement_time = p1;
  att.details.time_source = 4;
  att.details.p1_time = p1;
  att.solution_type = 4;
  att.ypr_deg = {135.5f, -1.25f, 0.5f};
  att.ypr_std_deg = {0.25f, 0.5f, 1.0f};
  att.baseline_distance_m = 1.75f;
  att.baseline_distance_std_m = 0.01f;
  add(att, "\"solution_type\": 4, \"ypr_deg\": " + list(att.ypr_deg) + ", \"ypr_std_deg\": " + list(att.ypr_std_deg) +
               ", \"baseline_distance_m\": 1.75");

  VersionInfoMessage ver;
  ver.system_time_ns = 123456789;
  ver.fw_version = "navfuse 0.1.0";
  ver.engine_version = "1.25.0";
  ver.os_version = "linux";
  ver.rx_version = "sim";
  add(ver, "\"system_time_ns\": 123456789, \"fw_version_str\": \"navfuse 0.1.0\", \"engine_version_str\": \"1.25.0\", "
           "\"os_version_str\": \"linux\", \"rx_version_str\": \"sim\"");

  EventNotificationMessage ev;
  ev.event_type = 1;
  ev.system_time_ns = 987654321;
  ev.event_flags = 0xFFF;
  ev.description = "cold start";
  add(ev, "\"event_type\": 1, \"system_time_ns\": 987654321, \"event_flags\": 4095, \"event_description\": \"cold start\"");

  SystemStatusMessage st;
  st.p1_time = p1;
  st.gnss_temperature = 45 * 128 + 64;  // 45.5 deg C
  st.pe_cpu_temperature = 60 * 128;
  add(st, "\"gnss_temperature_degc\": 45.5, \"pe_cpu_temperature_degc\": 60.0");

  ResetRequestMessage rr;
  rr.reset_mask = reset::kColdStart;
  add(rr, "\"reset_mask\": 4095");
  SetConfigMessage sc;
  sc.config_type = to_u16(ConfigType::kGnssLeverArm);
  sc.flags = 1;
  sc.value = pack_config(Point3f{{1.5f, 0.25f, 0.75f}});
  add(sc, "\"config_object_lever_arm\": [1.5, 0.25, 0.75]");
  GetConfigMessage gc;
  gc.config_type = to_u16(ConfigType::kGnssLeverArm);
  gc.source = 1;
  add(gc, "\"config_type\": 18, \"request_source\": 1");
  SaveConfigMessage sv;
  sv.action = 2;
  add(sv, "\"action\": 2");
  SetMessageRateMessage smr;
  smr.output_interface = {1, 1};
  smr.protocol = 1;
  smr.flags = 1;
  smr.message_id = 10000;
  smr.rate = 6;
  add(smr, "\"protocol\": 1, \"flags\": 1, \"message_id\": 10000, \"rate\": 6");
  GetMessageRateMessage gmr;
  gmr.output_interface = {1, 1};
  gmr.protocol = 1;
  gmr.source = 0;
  gmr.message_id = 10000;
  add(gmr, "\"protocol\": 1, \"message_id\": 10000");
  MessageRequestMessage mr;
  mr.message_type = 13003;
  add(mr, "\"message_type\": 13003");
  CommandResponseMessage cr{17, 3};
  add(cr, "\"source_sequence_num\": 17, \"response\": 3");
  ConfigResponseMessage cfr;
  cfr.source = 0;
  cfr.config_type = to_u16(ConfigType::kGnssLeverArm);
  cfr.response = 0;
  cfr.value = pack_config(Point3f{{1.5f, 0.25f, 0.75f}});
  add(cfr, "\"config_object_lever_arm\": [1.5, 0.25, 0.75], \"response\": 0");
  MessageRateResponseMessage mrr;
  mrr.source = 0;
  mrr.response = 0;
  mrr.output_interface = {1, 1};
  MessageRateEntry e;
  e.protocol = 1;
  e.message_id = 10000;
  e.configured_rate = 6;
  e.effective_rate = 6;
  mrr.rates.push_back(e);
  add(mrr, "\"num_rates\": 1, \"rates0_message_id\": 10000, \"rates0_configured_rate\": 6");

  std::ofstream(argv[1], std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                 static_cast<std::streamsize>(bytes.size()));
  std::ofstream json(argv[2]);
  json << "[\n";
  for (std::size_t i = 0; i < expected.size(); ++i) json << "  " << expected[i] << (i + 1 < expected.size() ? ",\n" : "\n");
  json << "]\n";
  return 0;
}
