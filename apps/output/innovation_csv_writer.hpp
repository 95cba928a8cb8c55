// --innovations-csv: one row per aiding measurement the filter looked at, the first time its
// outcome is known (a late measurement re-fused by re-propagation is not written twice). What a
// user needs to see why fixes were used or rejected, and whether the filter is consistent
// (NIS per dimension ~1). Columns (header row first):
//   time_s        the measurement's own time (seconds, on the time base of --csv's time_s)
//   kind          measurement kind (core to_string(MeasurementKind))
//   fix           GNSS fix type for GNSS kinds (rtk_fixed, rtk_float, ...), empty otherwise
//   result        used | the reject reason (chi2_gate, not_aligned, ...)
//   rows          dimension of the update tried (0: none was, e.g. not_aligned)
//   nis           r^T S^-1 r of that update
//   r0, r1, r2    residual h(x) - z per row, in the measurement's units (m, m/s, rad)
//   s0, s1, s2    sqrt(diag S): the residual's predicted std per row
#pragma once

#include <string>

#include "apps/output/output_file.hpp"
#include "core/measurements/measurements.hpp"
#include "filter/filter_core.hpp"

namespace navfuse::apps {

class InnovationCsvWriter {
 public:
  explicit InnovationCsvWriter(const std::string& path);
  void write(const Measurement& m, const filter::FuseResult& result);
  void commit() { file_.commit(); }

  // filter::Engine::InnovationSink: `context` is the writer.
  static void sink(void* context, const Measurement& m, const filter::FuseResult& result) {
    static_cast<InnovationCsvWriter*>(context)->write(m, result);
  }

 private:
  OutputFile file_;
  std::string row_;  // reused
};

}  // namespace navfuse::apps
