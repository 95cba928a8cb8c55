// Test helper: waits for one message on NAVFUSE_AID_HEADING and prints its fields, or exits 2
// after a timeout. Usage: navfuse_aid_listen LCM_URL TIMEOUT_MS
#include <cstdio>
#include <cstdlib>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "navfuse/aid_heading_t.hpp"

namespace {
struct Receiver {
  bool got = false;
  void on(const lcm::ReceiveBuffer*, const std::string&, const navfuse::aid_heading_t* m) {
    std::printf("heading_deg=%.3f std_deg=%.3f valid=%d time_gps_ns=%lld\n", m->heading_deg, m->std_deg,
                m->valid, static_cast<long long>(m->time_gps_ns));
    std::fflush(stdout);
    got = true;
  }
};
}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return 64;
  lcm::LCM lcm(argv[1]);
  if (!lcm.good()) return 3;
  Receiver r;
  lcm.subscribe("NAVFUSE_AID_HEADING", &Receiver::on, &r);
  std::printf("ready\n");
  std::fflush(stdout);
  const int timeout_ms = std::atoi(argv[2]);
  for (int waited = 0; !r.got && waited < timeout_ms; waited += 100) lcm.handleTimeout(100);
  return r.got ? 0 : 2;
}
