// The time series `navfuse bench --report DIR` writes next to metrics.json, for the report's plots
// and for users' own analysis. Times are t_s, seconds since the log's first IMU sample, plus
// time_s on the log's own time base. Positions are also given as east/north/up metres from a
// common origin (navfuse's first navigation position) so tracks plot on one map. A quantity a
// sample does not carry is "nan".
//
//   navfuse.csv, device.csv  every solution sample: mode, position, velocity, attitude, 1-sigma
//   truth.csv                truth at navfuse's pose times (with --truth)
//   <pair>.csv               aligned errors of each compared pair, estimate - reference, with the
//                            1-sigma of each axis and the phase labels
//   phases.csv               GNSS outage and stationary intervals
#pragma once

#include <string>

#include "apps/bench/bench_analysis.hpp"
#include "apps/bench/bench_log.hpp"

namespace navfuse::apps::bench {

// Writes every CSV into `dir` (which must exist); throws CommandError naming a file that cannot
// be written.
void write_series_csvs(const std::string& dir, const BenchLog& log, const BenchAnalysis& analysis);

}  // namespace navfuse::apps::bench
