#include "apps/aid/aid_command.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include "apps/aid/aid_message.hpp"
#include "apps/common/command_error.hpp"
#include "apps/common/command_help.hpp"
#include "apps/lcm/lcm_open.hpp"
#include "core/time/gps_time.hpp"

namespace navfuse::apps {
namespace {

struct AidOptions {
  AidSpec spec;
  std::string csv;
  std::string lcm_url;  // empty: LCM's default (LCM_DEFAULT_URL or udpm)
  double time_gps_s = -1.0;
  double rate_hz = 0.0;  // CSV replay rate; 0 = as fast as possible
  bool quiet = false;
};

std::int64_t gps_now_ns() {
  const auto unix_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                           std::chrono::system_clock::now().time_since_epoch()).count();
  return time::gps_ns_from_unix_ns(unix_ns);
}

void publish(lcm::LCM& lcm, const AidMessage& m) {
  std::visit([&](const auto& msg) {
    if (lcm.publish(aid_channel(m), &msg) != 0) throw CommandError(std::string("LCM publish failed on ") + aid_channel(m));
  }, m);
}

int run_aid(AidOptions& opt) {
  std::vector<AidMessage> messages;
  if (!opt.csv.empty()) {
    for (const auto& row : read_aid_csv(opt.csv)) messages.push_back(make_aid_message(row));
  } else {
    if (opt.spec.kind.empty()) throw CommandError("aid: give KIND and values, or --csv FILE");
    // Whole seconds and fraction converted apart: GPS seconds (~1.4e9) times 1e9 exceeds the
    // 2^53 integers a double holds exactly.
    if (opt.time_gps_s >= 0) {
      const double whole = std::floor(opt.time_gps_s);
      opt.spec.time_gps_ns = static_cast<std::int64_t>(whole) * time::kNsPerSecond +
                             std::llround((opt.time_gps_s - whole) * 1e9);
    } else {
      opt.spec.time_gps_ns = gps_now_ns();
    }
    messages.push_back(make_aid_message(opt.spec));
  }
  lcm::LCM lcm(opt.lcm_url);
  require_lcm_open(lcm, opt.lcm_url);
  for (const auto& m : messages) {
    publish(lcm, m);
    if (opt.rate_hz > 0) std::this_thread::sleep_for(std::chrono::duration<double>(1.0 / opt.rate_hz));
  }
  if (!opt.quiet) std::cerr << "navfuse aid: published " << messages.size() << " message(s)\n";
  return 0;
}

}  // namespace

void add_aid_command(CLI::App& root, int& exit_code) {
  auto opt = std::make_shared<AidOptions>();
  CLI::App* sub = root.add_subcommand("aid", "Send external aiding (position, velocity, heading, speed) over LCM");
  sub->add_option("KIND", opt->spec.kind, "position | velocity | heading | speed");
  sub->add_option("VALUES", opt->spec.values,
                  "position: lat_deg lon_deg height_m (or ECEF x y z); velocity: 3 components m/s; "
                  "heading: deg from true north; speed: m/s");
  sub->add_option("--std", opt->spec.std, "1-sigma uncertainty (one value or one per axis), same units");
  sub->add_option("--frame", opt->spec.frame, "llh|ecef for position, ned|ecef|vehicle for velocity");
  sub->add_option("--lever-arm", opt->spec.lever_arm_m, "sensor position in the vehicle frame, m (x y z)");
  sub->add_option("--time-gps-s", opt->time_gps_s, "measurement time, GPS seconds (default: now)");
  sub->add_option("--csv", opt->csv, "send every row of a CSV: kind,time_gps_s,frame,v1,v2,v3,std1,std2,std3");
  sub->add_option("--rate-hz", opt->rate_hz, "pace CSV rows at this rate (default: as fast as possible)");
  sub->add_option("--lcm", opt->lcm_url, "LCM URL (default: LCM_DEFAULT_URL or udpm multicast)");
  add_quiet_flag(sub, opt->quiet, "count of messages published");
  add_examples(sub, {{"a heading of 92.5 deg, 1 deg 1-sigma, to the nav process on LCM's default URL",
                      "navfuse aid heading 92.5 --std 1.0"},
                     {"every row of a CSV at 10 Hz, on a loopback-only LCM",
                      "navfuse aid --csv aiding.csv --rate-hz 10 --lcm 'udpm://239.255.76.67:7667?ttl=0'"}});
  sub->callback([opt, &exit_code] { exit_code = run_aid(*opt); });
}

}  // namespace navfuse::apps
