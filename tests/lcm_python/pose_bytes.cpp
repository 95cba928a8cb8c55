// Writes one navfuse pose_t encoded by the C++ LCM bindings, and the values it holds, as JSON:
// {"hex": "<encoded message, with fingerprint>", "fields": {...}}, for decode_test.py to check
// that the Python bindings generated from the same .lcm decode it to the same values.
#include <cstdio>
#include <iostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "navfuse/pose_t.hpp"

int main() {
  navfuse::pose_t p{};
  p.time_gps_ns = 1'391'342'407'565'000'123;
  p.mode = 4;
  p.gnss_fix = 3;
  p.status_flags = 0x105;
  p.valid = -7;  // all bits but one and two: sign handling of int32
  p.lat_deg = 45.123456789012;
  p.lon_deg = -7.654321098765;
  p.height_m = 312.625;
  p.undulation_m = -32.16;
  nlohmann::ordered_json fields = {{"time_gps_ns", p.time_gps_ns}, {"mode", p.mode},     {"gnss_fix", p.gnss_fix},
                                   {"status_flags", p.status_flags}, {"valid", p.valid}, {"lat_deg", p.lat_deg},
                                   {"lon_deg", p.lon_deg},         {"height_m", p.height_m},
                                   {"undulation_m", p.undulation_m}};
  for (int i = 0; i < 3; ++i) {
    p.vel_ned_mps[i] = 1.5f * static_cast<float>(i + 1);
    p.rpy_deg[i] = -10.25f * static_cast<float>(i + 1);
    p.gyro_bias_dps[i] = 0.001f * static_cast<float>(i + 1);
  }
  for (int i = 0; i < 4; ++i) p.q_nb_wxyz[i] = 0.5 * (i % 2 == 0 ? 1 : -1);
  fields["vel_ned_mps"] = std::vector<float>(p.vel_ned_mps, p.vel_ned_mps + 3);
  fields["rpy_deg"] = std::vector<float>(p.rpy_deg, p.rpy_deg + 3);
  fields["gyro_bias_dps"] = std::vector<float>(p.gyro_bias_dps, p.gyro_bias_dps + 3);
  fields["q_nb_wxyz"] = std::vector<double>(p.q_nb_wxyz, p.q_nb_wxyz + 4);

  std::vector<unsigned char> bytes(static_cast<std::size_t>(p.getEncodedSize()));
  p.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  std::string hex;
  for (unsigned char b : bytes) {
    char two[3];
    std::snprintf(two, sizeof two, "%02x", b);
    hex += two;
  }
  std::cout << nlohmann::ordered_json{{"hex", hex}, {"fields", fields}}.dump() << "\n";
  return 0;
}
