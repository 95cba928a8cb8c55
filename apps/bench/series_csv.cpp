#include "apps/bench/series_csv.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "apps/common/command_error.hpp"
#include "core/geodesy/geodesy.hpp"
#include "core/rotation/rotation.hpp"

namespace navfuse::apps::bench {
namespace {

constexpr double kRad2Deg = rot::kRadToDeg;

class CsvFile {
 public:
  explicit CsvFile(const std::string& path) : path_(path), out_(path) {
    if (!out_) throw CommandError("cannot write '" + path + "'");
  }
  void close() {
    out_.close();
    if (!out_) throw CommandError("error writing '" + path_ + "'");
  }
  std::ofstream& out() { return out_; }

 private:
  std::string path_;
  std::ofstream out_;
};

// Fixed-point text for a value, "nan" when absent, so every file parses the same way.
std::string num(double v, int decimals) {
  if (!std::isfinite(v)) return "nan";
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

// "123.456789012": exact nanoseconds, whatever the magnitude.
std::string time_text(std::int64_t ns) {
  char text[40];
  const std::int64_t s = ns / 1'000'000'000, frac = ns % 1'000'000'000;
  if (ns < 0 && frac != 0) {
    std::snprintf(text, sizeof text, "-%lld.%09lld", static_cast<long long>(-(ns / 1'000'000'000)),
                  static_cast<long long>(-frac));
  } else {
    std::snprintf(text, sizeof text, "%lld.%09lld", static_cast<long long>(s), static_cast<long long>(frac));
  }
  return text;
}

struct Origin {
  geo::Llh llh;
  bool set = false;
};

Origin common_origin(const BenchLog& log, const BenchAnalysis& a) {
  for (const SolutionTrack* track : {&log.navfuse, &log.device}) {
    if (const auto s = track->with(Quantity::kPosition, track == &log.navfuse).front()) {
      return {{s->lat_rad, s->lon_rad, s->height_m}, true};
    }
  }
  SpillFile<TrackSample>::Reader truth = a.truth_at_poses.reader();
  if (TrackSample t; truth.next(t)) return {{t.lat_rad, t.lon_rad, t.height_m}, true};
  return {};
}

void write_track(const std::string& path, SpillFile<TrackSample>::Reader samples, std::int64_t start_ns,
                 const Origin& origin) {
  CsvFile f(path);
  auto& o = f.out();
  o << "t_s,time_s,mode,east_m,north_m,up_m,lat_deg,lon_deg,height_m,vn_mps,ve_mps,vd_mps,roll_deg,pitch_deg,"
       "yaw_deg,std_north_m,std_east_m,std_down_m,std_vn_mps,std_ve_mps,std_vd_mps,std_roll_deg,std_pitch_deg,"
       "std_yaw_deg,gnss_outage,stationary\n";
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  for (TrackSample s; samples.next(s);) {
    // Before a solution has an estimate its fields are zeros rather than estimates, even if flagged.
    const bool estimating = s.mode > NavMode::kInitializing;
    const bool pos = estimating && has(s, Quantity::kPosition), vel = estimating && has(s, Quantity::kVelocity);
    const bool att = estimating && has(s, Quantity::kAttitude), hdg = estimating && has(s, Quantity::kHeading);
    Eigen::Vector3d ned = Eigen::Vector3d::Constant(kNan);
    if (pos && origin.set) ned = geo::ned_offset_m(origin.llh, {s.lat_rad, s.lon_rad, s.height_m});
    const auto pick = [](bool ok, double v) { return ok ? v : kNan; };
    const bool pos_std = pos && has_std(s, Quantity::kPosition), vel_std = vel && has_std(s, Quantity::kVelocity);
    const bool att_std = att && has_std(s, Quantity::kAttitude);
    o << num(static_cast<double>(s.time_ns - start_ns) * 1e-9, 3) << ',' << time_text(s.time_ns) << ','
      << to_string(s.mode) << ',' << num(ned.y(), 3) << ',' << num(ned.x(), 3) << ',' << num(-ned.z(), 3) << ','
      << num(pick(pos, s.lat_rad * kRad2Deg), 9) << ',' << num(pick(pos, s.lon_rad * kRad2Deg), 9) << ','
      << num(pick(pos, s.height_m), 3);
    for (int i = 0; i < 3; ++i) o << ',' << num(pick(vel, s.vel_ned_mps[i]), 4);
    o << ',' << num(pick(att, s.rpy_rad.x() * kRad2Deg), 4) << ',' << num(pick(att, s.rpy_rad.y() * kRad2Deg), 4)
      << ',' << num(pick(hdg, s.rpy_rad.z() * kRad2Deg), 4);
    for (int i = 0; i < 3; ++i) o << ',' << num(pick(pos_std, s.pos_std_ned_m[i]), 4);
    for (int i = 0; i < 3; ++i) o << ',' << num(pick(vel_std, s.vel_std_ned_mps[i]), 4);
    for (int i = 0; i < 3; ++i) o << ',' << num(pick(att_std, s.att_std_rpy_rad[i] * kRad2Deg), 4);
    o << ',' << ((s.status_flags & NavSolution::kStatusGnssOutage) ? 1 : 0) << ','
      << ((s.status_flags & NavSolution::kStatusStationary) ? 1 : 0) << '\n';
  }
  f.close();
}

void write_pair(const std::string& path, const PairComparison& pair, std::int64_t start_ns) {
  CsvFile f(path);
  auto& o = f.out();
  o << "t_s,time_s,estimate_mode,gnss_outage,stationary,err_north_m,err_east_m,err_down_m,horizontal_m,vertical_m,"
       "position_3d_m,err_vn_mps,err_ve_mps,err_vd_mps,velocity_mps,err_roll_deg,err_pitch_deg,err_heading_deg,"
       "sigma_north_m,sigma_east_m,sigma_down_m,sigma_vn_mps,sigma_ve_mps,sigma_vd_mps,sigma_roll_deg,"
       "sigma_pitch_deg,sigma_heading_deg\n";
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  SpillFile<AlignedError>::Reader rows = pair.errors.reader();
  for (AlignedError row; rows.next(row);) {
    const SolutionError& e = row.error;
    const auto& label = row.phase;
    o << num(static_cast<double>(e.time_ns - start_ns) * 1e-9, 3) << ',' << time_text(e.time_ns) << ','
      << to_string(e.estimate_mode) << ',' << (label ? (label->gnss_outage ? "1" : "0") : "nan") << ','
      << (label ? (label->stationary ? "1" : "0") : "nan");
    std::string sigmas;
    for (std::size_t a = 0; a < kAxisCount; ++a) {
      const auto err = axis_error(e, static_cast<Axis>(a));
      const double scale = a >= static_cast<std::size_t>(Axis::kRoll) ? kRad2Deg : 1.0;
      const double value = err ? err->first * scale : kNan;
      const double sigma = err ? err->second * scale : kNan;
      o << ',' << num(value, 4);
      sigmas += ',' + num(sigma, 4);
      if (a == static_cast<std::size_t>(Axis::kDown)) {
        for (Metric m : {Metric::kHorizontal, Metric::kVertical, Metric::kPosition3d}) {
          o << ',' << num(metric_value(e, m).value_or(kNan), 4);
        }
      } else if (a == static_cast<std::size_t>(Axis::kVelDown)) {
        o << ',' << num(metric_value(e, Metric::kVelocity).value_or(kNan), 4);
      }
    }
    o << sigmas << '\n';
  }
  f.close();
}

void write_phases(const std::string& path, const PhaseTimeline& phases, std::int64_t start_ns) {
  CsvFile f(path);
  auto& o = f.out();
  o << "phase,start_s,end_s,source\n";
  const auto rows = [&](const char* name, const std::vector<TimeInterval>& list) {
    for (const auto& iv : list) {
      o << name << ',' << num(static_cast<double>(iv.start_ns - start_ns) * 1e-9, 3) << ','
        << num(static_cast<double>(iv.end_ns - start_ns) * 1e-9, 3) << ',' << phases.source() << '\n';
    }
  };
  rows("gnss_outage", phases.outages());
  rows("stationary", phases.stationary_periods());
  f.close();
}

}  // namespace

void write_series_csvs(const std::string& dir, const BenchLog& log, const BenchAnalysis& analysis) {
  const Origin origin = common_origin(log, analysis);
  write_track(dir + "/navfuse.csv", log.navfuse.reader(), log.start_ns, origin);
  if (!log.device.empty()) write_track(dir + "/device.csv", log.device.reader(), log.start_ns, origin);
  if (!analysis.truth_at_poses.empty()) {
    write_track(dir + "/truth.csv", analysis.truth_at_poses.reader(), log.start_ns, origin);
  }
  for (const PairComparison& pair : analysis.pairs) write_pair(dir + "/" + pair.spec.name + ".csv", pair, log.start_ns);
  write_phases(dir + "/phases.csv", analysis.phases, log.start_ns);
}

}  // namespace navfuse::apps::bench
