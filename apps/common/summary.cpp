#include "apps/common/summary.hpp"

#include <iomanip>

#include "apps/common/command_error.hpp"
#include "apps/common/rejection_warning.hpp"
#include "apps/output/output_file.hpp"

namespace navfuse::apps {
namespace {

nlohmann::ordered_json innovation_json(const InnovationSummary& in) {
  return {{"count", in.count},
          {"mean_nis", in.mean_nis},
          {"mean_nis_per_dim", in.mean_nis_per_dim},
          {"fraction_above_gate", in.fraction_above_gate}};
}

void print_innovation_line(std::ostream& os, std::string_view name, const InnovationSummary& in) {
  os << "  " << std::left << std::setw(18) << name << std::right << " count " << std::setw(8) << in.count
     << "  mean NIS/dim " << std::fixed << std::setprecision(2) << std::setw(7) << in.mean_nis_per_dim
     << "  above gate " << std::setprecision(1) << std::setw(5) << 100.0 * in.fraction_above_gate << " %\n"
     << std::defaultfloat;
}

constexpr const char* kInnovationsHeader = "innovations (updates tried; a consistent filter has NIS per dimension ~1):\n";

}  // namespace

nlohmann::ordered_json Summary::to_json(bool decode_only) const {
  nlohmann::ordered_json j;
  j["inputs"] = nlohmann::ordered_json::array();
  for (const auto& in : inputs) {
    j["inputs"].push_back({{"path", in.path},
                           {"format", in.format},
                           {"bytes", in.counters.bytes},
                           {"frames", in.counters.frames},
                           {"bad_frames", in.counters.bad_frames},
                           {"skipped_bytes", in.counters.skipped_bytes},
                           {"unknown_frames", in.counters.unknown_frames},
                           {"decode_errors", in.counters.decode_errors}});
  }
  nlohmann::ordered_json m = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const auto& ks = kinds[k];
    nlohmann::ordered_json e;
    e["decoded"] = ks.decoded;
    if (!decode_only) {
      e["used"] = ks.used;
      e["rejected"] = nlohmann::ordered_json::object();
      for (const auto& [reason, n] : ks.rejected) e["rejected"][reason] = n;
      if (ks.innovation) e["innovation"] = innovation_json(*ks.innovation);
      e["pending_at_end"] = ks.pending;
    }
    m[std::string(to_string(static_cast<MeasurementKind>(k)))] = e;
  }
  j["measurements"] = m;
  if (run) {
    j["run"] = {{"wall_s", run->wall_s},
                {"imu_samples_per_s", run->imu_samples_per_s},
                {"modes_reached", run->modes_reached}};
    if (interrupted_by != 0) j["run"]["interrupted_by_signal"] = interrupted_by;
  } else if (interrupted_by != 0) {
    j["interrupted_by_signal"] = interrupted_by;
  }
  if (!decode_only) {
    const std::vector<std::string> warnings = rejection_warnings(kinds);
    if (!warnings.empty()) j["warnings"] = warnings;
  }
  if (adaptation && !decode_only) {
    j["filter"] = {{"covariance_inflations", adaptation->covariance_inflations},
                   {"process_noise_scale", adaptation->process_noise_scale},
                   {"max_process_noise_scale", adaptation->max_process_noise_scale},
                   {"gnss_recoveries", adaptation->gnss_recoveries},
                   {"max_gnss_position_noise_scale", adaptation->max_gnss_position_noise_scale},
                   {"max_gnss_velocity_noise_scale", adaptation->max_gnss_velocity_noise_scale},
                   {"output_jumps_blended", adaptation->output_jumps_blended}};
  }
  if (nhc && !decode_only) {
    nlohmann::ordered_json c = {{"updates", nhc_updates}};
    c.update(innovation_json(*nhc));
    j["constraints"]["nhc"] = c;
  }
  if (!calibration.empty() && !decode_only) {
    nlohmann::ordered_json c = nlohmann::ordered_json::object();
    for (const CalibrationGroup& g : calibration) {
      for (bool is_std : {false, true}) {
        for (int i = 0; i < g.count; ++i) {
          c[g.column(i, is_std)] = (is_std ? g.std : g.value)[static_cast<std::size_t>(i)];
        }
      }
    }
    j["calibration"] = c;
  }
  for (const auto& [key, value] : extra.items()) j[key] = value;
  return j;
}

void Summary::print(std::ostream& os, bool decode_only) const {
  for (const auto& in : inputs) {
    const auto& c = in.counters;
    os << in.path << " [" << in.format << "]: " << c.bytes << " bytes, " << c.frames << " frames, "
       << c.bad_frames << " bad frames, " << c.skipped_bytes << " bytes skipped";
    if (c.unknown_frames) os << ", " << c.unknown_frames << " unknown frames";
    if (c.decode_errors) os << ", " << c.decode_errors << " decode errors";
    os << "\n";
  }
  os << "measurements:\n";
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const auto& ks = kinds[k];
    std::uint64_t rejected = 0;
    for (const auto& [reason, n] : ks.rejected) rejected += n;
    if (ks.decoded == 0 && ks.used == 0 && rejected == 0) continue;
    os << "  " << std::left << std::setw(18) << to_string(static_cast<MeasurementKind>(k)) << std::right
       << " decoded " << std::setw(8) << ks.decoded;
    if (!decode_only) {
      os << "  used " << std::setw(8) << ks.used << "  rejected " << std::setw(6) << rejected;
      bool first = true;
      for (const auto& [reason, n] : ks.rejected) {
        os << (first ? " (" : ", ") << reason << ": " << n;
        first = false;
      }
      if (!first) os << ")";
      if (ks.pending > 0) os << "  pending at end " << ks.pending;
    }
    os << "\n";
  }
  if (!decode_only) {
    print_innovations(os);
    print_calibration(os);
  }
  if (run) {
    os << "run: " << std::fixed << std::setprecision(3) << run->wall_s << " s wall, " << std::setprecision(0)
       << run->imu_samples_per_s << " IMU samples/s; modes reached:";
    for (const auto& mode : run->modes_reached) os << " " << mode;
    os << "\n" << std::defaultfloat;
  }
  if (!decode_only) {
    for (const std::string& warning : rejection_warnings(kinds)) os << "warning: " << warning << "\n";
  }
  if (interrupted_by != 0) {
    os << "interrupted by signal " << interrupted_by << ": stopped early, outputs hold what was processed\n";
  }
}

void Summary::print_innovations(std::ostream& os) const {
  bool header = false;
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const auto& in = kinds[k].innovation;
    if (!in || in->count == 0) continue;
    if (!header) {
      os << kInnovationsHeader;
      header = true;
    }
    print_innovation_line(os, to_string(static_cast<MeasurementKind>(k)), *in);
  }
  if (nhc && nhc->count > 0) {
    if (!header) os << kInnovationsHeader;
    print_innovation_line(os, "nhc (constraint)", *nhc);
    os << "    (its std is a tolerance: far below 1 where the vehicle does not slip at nhc.lever_arm_m)\n";
  }
  if (adaptation && (adaptation->covariance_inflations > 0 || adaptation->max_process_noise_scale > 1.0 ||
                     adaptation->gnss_recoveries > 0 || adaptation->max_gnss_position_noise_scale > 1.0 ||
                     adaptation->max_gnss_velocity_noise_scale > 1.0 || adaptation->output_jumps_blended > 0)) {
    os << "filter adaptation: " << adaptation->covariance_inflations << " covariance re-inflations, "
       << adaptation->gnss_recoveries << " GNSS re-anchors; process noise scale " << std::fixed
       << std::setprecision(2) << adaptation->process_noise_scale << " at the end (max "
       << adaptation->max_process_noise_scale << "); GNSS variances scaled up to "
       << adaptation->max_gnss_position_noise_scale << "x (position), " << adaptation->max_gnss_velocity_noise_scale
       << "x (velocity)";
    if (adaptation->output_jumps_blended > 0) {
      os << "; " << adaptation->output_jumps_blended << " position corrections blended into the output";
    }
    os << "\n" << std::defaultfloat;
  }
}

void Summary::print_calibration(std::ostream& os) const {
  if (calibration.empty()) return;
  os << "calibration at the end (value +- 1 sigma):\n";
  for (const CalibrationGroup& g : calibration) {
    os << "  " << std::left << std::setw(21) << g.name << std::setw(6) << g.unit << std::right << std::fixed
       << std::setprecision(g.decimals);
    for (int i = 0; i < g.count; ++i) {
      const auto a = static_cast<std::size_t>(i);
      os << (g.axes[a].empty() ? "" : " ") << g.axes[a] << ' ' << g.value[a] << " +- " << g.std[a];
    }
    os << "\n" << std::defaultfloat;
  }
}

void write_json_file(const std::string& path, const nlohmann::ordered_json& j) {
  OutputFile out(path);
  out.write(j.dump(2));
  out.write(std::string_view("\n"));
  out.commit();
}

}  // namespace navfuse::apps
