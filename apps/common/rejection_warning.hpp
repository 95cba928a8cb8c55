// The summary's warning when most of a log's IMU or GNSS samples were thrown away (issue 15,
// "exit codes"): a run can reach navigation and exit 0 while most of its data went to
// time_jump, chi2_gate or time_base, and the counts alone are easy to miss. Samples rejected as
// not_aligned are not counted: the filter refuses aiding until it has an attitude, which is
// waiting, not a fault.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "apps/common/summary.hpp"

namespace navfuse::apps {

// One line per kind (IMU, GNSS position / velocity / heading) with more than half of its decoded
// samples rejected for other reasons than not_aligned: "most IMU samples were rejected: 30000 of
// 38000 (time_jump: 29000, ...)". Empty when none.
std::vector<std::string> rejection_warnings(const std::array<KindSummary, static_cast<std::size_t>(MeasurementKind::kCount)>& kinds);

}  // namespace navfuse::apps
