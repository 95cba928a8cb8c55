#include "apps/bench/bench.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "apps/bench/bench_analysis.hpp"
#include "apps/bench/bench_log.hpp"
#include "apps/bench/report_renderer.hpp"
#include "apps/bench/series_csv.hpp"
#include "apps/common/command_error.hpp"
#include "apps/common/interrupt_signals.hpp"
#include "apps/common/rejection_warning.hpp"
#include "apps/common/summary.hpp"

namespace navfuse::apps::bench {
namespace {

std::string summary_text(const BenchAnalysis& a) {
  std::ostringstream os;
  char line[200];
  for (const PairComparison& p : a.pairs) {
    std::snprintf(line, sizeof line, "%s: %zu samples over %.1f s\n", p.spec.name.c_str(), p.samples(), p.overlap_s());
    os << line;
    std::snprintf(line, sizeof line, "  %-14s %10s %10s %10s %10s %10s\n", "", "rms", "p50", "p95", "p99", "max");
    os << line;
    for (std::size_t m = 0; m < kMetricCount; ++m) {
      const ErrorSummary s = p.metrics.all().summary(static_cast<Metric>(m));
      if (s.samples == 0) continue;
      std::snprintf(line, sizeof line, "  %-14s %10.3f %10.3f %10.3f %10.3f %10.3f\n",
                    std::string(metric_key(static_cast<Metric>(m))).c_str(), s.rms, s.p50, s.p95, s.p99, s.max);
      os << line;
    }
  }
  return os.str();
}

}  // namespace

BenchResult run_bench(const BenchOptions& options) {
  if (options.report_dir.empty()) throw CommandError("bench needs --report DIR");
  std::error_code ec;
  std::filesystem::create_directories(options.report_dir, ec);
  if (ec || !std::filesystem::is_directory(options.report_dir)) {
    throw CommandError("cannot create report folder '" + options.report_dir + "'");
  }
  if (!options.reference.empty() && options.reference != "smoothed") {
    throw CommandError("--reference: '" + options.reference + "' is not a reference bench knows (smoothed)");
  }
  const bool smoothed = options.reference == "smoothed";
  const BenchLog log = collect_bench_log({.inputs = options.inputs,
                                          .gps_week = options.gps_week,
                                          .config_path = options.config_path,
                                          .allow_truncated = options.allow_truncated,
                                          .progress = options.progress,
                                          .smooth = smoothed,
                                          .interrupt = options.interrupt});
  const int interrupted_by = log.summary.interrupted_by;
  const AnalysisOptions analysis_options{
      .truth_path = options.truth_path, .max_gap_s = options.max_gap_s, .smoothed_reference = smoothed};
  const BenchAnalysis analysis = [&] {
    try {
      return analyse(log, analysis_options);
    } catch (const CommandError& e) {
      if (interrupted_by == 0) throw;
      throw CommandError("bench interrupted by signal " + std::to_string(interrupted_by) +
                             " before there was anything to compare: " + e.what(),
                         interrupted_exit_code(interrupted_by));
    }
  }();
  const nlohmann::ordered_json metrics = analysis.metrics_json(log, analysis_options);
  write_json_file(options.report_dir + "/metrics.json", metrics);
  write_series_csvs(options.report_dir, log, analysis);
  if (options.html) render_report_html(options.report_dir);

  BenchResult result;
  result.notes = analysis.notes;
  result.summary_text = summary_text(analysis);
  result.warnings = rejection_warnings(log.summary.kinds);
  result.interrupted_by = interrupted_by;
  if (interrupted_by != 0) {
    char line[160];
    std::snprintf(line, sizeof line, "interrupted by signal %d: the report covers the first %.1f s of the log\n",
                  interrupted_by, static_cast<double>(log.end_ns - log.start_ns) * 1e-9);
    result.summary_text += line;
  }
  result.exceeded = exceeded_thresholds(options.fail_above, metrics);
  return result;
}

}  // namespace navfuse::apps::bench
