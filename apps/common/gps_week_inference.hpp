// The GPS week of an input timed by seconds of week only (imutxt), taken from the other inputs of
// the same run: research data sets ship the IMU as seconds of week beside a GNSS solution with
// full GPS time (KF-GINS data, the RTKLIB .pos of the walk_0827 capture), so the week is in the
// data already and a user should not have to look it up.
//
// The first GPS-timed measurement in the first 64 KiB of each other input is the reference; the
// week is the one that puts the input's first seconds of week closest to it, so a log that starts
// just before a Sunday rollover and a GNSS file that starts just after still agree.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "apps/common/input_spec.hpp"

namespace navfuse::apps {

// nullopt when no other input has a GPS-timed measurement in its head, or `spec` has no sample.
std::optional<std::int32_t> infer_gps_week(const InputSpec& spec, const std::vector<InputSpec>& all);

// The week W that puts `tow_ns` (seconds of week as ns) closest to the GPS time `reference_ns`.
std::int32_t nearest_week(std::int64_t tow_ns, std::int64_t reference_ns);

}  // namespace navfuse::apps
