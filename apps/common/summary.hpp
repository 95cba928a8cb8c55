// The run summary of `navfuse decode` / `replay` / `bench`: per input stream counters, per
// measurement kind decoded / used / rejected-by-reason, and run statistics. Printed as text and
// written as JSON with the DESIGN.md keys (contract): inputs[] {path, format, bytes, frames,
// bad_frames, skipped_bytes}, measurements {kind: {decoded, used, rejected{reason: n}}},
// run {wall_s, imu_samples_per_s, modes_reached}. Added beside them: measurements.KIND.innovation
// {count, mean_nis, mean_nis_per_dim, fraction_above_gate}, measurements.KIND.pending_at_end,
// filter {covariance_inflations, process_noise_scale, max_process_noise_scale, gnss_recoveries,
//         max_gnss_position_noise_scale, max_gnss_velocity_noise_scale, output_jumps_blended},
// constraints.nhc {updates, count, mean_nis, mean_nis_per_dim, fraction_above_gate} (when the
// non-holonomic constraint was tried)
// and calibration {the CSV's calibration column names: value} at the end of the run.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/common/calibration_groups.hpp"
#include "core/measurements/measurements.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::apps {

struct InputSummary {
  std::string path;
  std::string format;
  frontends::StreamCounters counters;
};

// Innovations of the updates the filter tried for one kind (accepted or gated).
struct InnovationSummary {
  std::uint64_t count = 0;
  double mean_nis = 0.0;
  double mean_nis_per_dim = 0.0;  // ~1 for a consistent filter
  double fraction_above_gate = 0.0;
};

struct KindSummary {
  std::uint64_t decoded = 0;
  std::uint64_t used = 0;
  std::map<std::string, std::uint64_t> rejected;  // ordered: deterministic output
  std::uint64_t pending = 0;  // held at the end, neither used nor rejected: decoded = used + rejected + pending
  std::optional<InnovationSummary> innovation;    // kinds the filter tried to fuse
};

// How the filter adapted itself (filter/control/innovation_adaptation.hpp).
struct AdaptationSummary {
  std::uint64_t covariance_inflations = 0;
  double process_noise_scale = 1.0;  // at the end
  double max_process_noise_scale = 1.0;
  std::uint64_t gnss_recoveries = 0;  // re-anchored to GNSS after sustained rejection
  // Largest multipliers on the reported GNSS variances (control/measurement_noise_adaptation.hpp).
  double max_gnss_position_noise_scale = 1.0;
  double max_gnss_velocity_noise_scale = 1.0;
  // Position corrections the output took over output.jump_blend_s instead of at once
  // (filter/output_blend.hpp).
  std::uint64_t output_jumps_blended = 0;
};

struct RunStats {
  double wall_s = 0.0;
  double imu_samples_per_s = 0.0;
  std::vector<std::string> modes_reached;
};

struct Summary {
  std::vector<InputSummary> inputs;
  std::array<KindSummary, static_cast<std::size_t>(MeasurementKind::kCount)> kinds{};
  std::optional<RunStats> run;  // absent for `decode`
  std::optional<AdaptationSummary> adaptation;  // absent for `decode`
  // The non-holonomic constraint's updates applied and innovations tried (absent when none were).
  std::uint64_t nhc_updates = 0;
  std::optional<InnovationSummary> nhc;
  // The estimated calibration states at the end of the run (the groups estimated; empty for
  // `decode` and before levelling).
  std::vector<CalibrationGroup> calibration;
  int interrupted_by = 0;       // the signal that stopped the run early (0: ran to the end)
  // Extra top-level sections (e.g. accuracy against truth) added by commands.
  nlohmann::ordered_json extra = nlohmann::ordered_json::object();

  KindSummary& kind(MeasurementKind k) { return kinds[static_cast<std::size_t>(k)]; }
  nlohmann::ordered_json to_json(bool decode_only) const;
  void print(std::ostream& os, bool decode_only) const;

 private:
  void print_innovations(std::ostream& os) const;
  void print_calibration(std::ostream& os) const;
};

// Writes JSON to `path` as an OutputFile (apps/output/output_file.hpp: a regular file appears
// whole, a device or FIFO is streamed to); throws CommandError on failure.
void write_json_file(const std::string& path, const nlohmann::ordered_json& j);

}  // namespace navfuse::apps
