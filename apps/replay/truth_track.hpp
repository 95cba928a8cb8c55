// A reference trajectory (`--truth`: navfuse CSV, RTKLIB .pos or KF-GINS .nav, truth_rows.hpp)
// read as a stream and interpolated at increasing query times, keeping only the two rows that
// bracket the query: memory stays constant however long the drive.
//
// Interpolation is linear in time for position, velocity and roll/pitch, and linear along the
// shorter arc for yaw. Dense references (navfuse's truth at the IMU rate, 200 Hz in the
// scenarios) are interpolated at every pose, where the linearisation error is far below the
// errors being measured (20 m/s * 5 ms = 0.1 m of travel per interval, interpolated to well under
// a millimetre). Sparse ones (GNSS solutions at 1-10 Hz) are instead read epoch by epoch
// (next_until) so that the poses are interpolated to them, not they to the poses.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "apps/replay/truth_rows.hpp"

namespace navfuse::apps {

class TruthTrack {
 public:
  // Opens "[rtklib:|nav:|csv:]PATH"; throws CommandError naming the file and the problem.
  explicit TruthTrack(const std::string& argument);

  // Truth at `time_ns`; nullopt outside the file's time span. Query times must not decrease
  // (earlier times than a previous query return nullopt). Throws CommandError on a malformed row.
  std::optional<TruthPoint> at(std::int64_t time_ns);

  // The next row at or before `time_ns`, in file order (each row once); nullopt when the next
  // row is later (it stays pending) or the file has ended. Not to be mixed with at().
  std::optional<TruthPoint> next_until(std::int64_t time_ns);

  std::uint64_t rows_read() const { return rows_; }
  std::string_view format() const { return rows_source_->format(); }
  ReferencePoint point() const { return rows_source_->point(); }
  bool sparse() const { return rows_source_->sparse(); }
  std::uint64_t rows_skipped() const { return rows_source_->rows_skipped(); }

 private:
  bool read_row(TruthPoint& out);

  std::unique_ptr<TruthRows> rows_source_;
  TruthPoint before_, after_;
  bool have_before_ = false, have_after_ = false, eof_ = false;
  std::uint64_t rows_ = 0;
  std::int64_t last_time_ns_ = 0;
};

}  // namespace navfuse::apps
