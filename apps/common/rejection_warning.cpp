#include "apps/common/rejection_warning.hpp"

namespace navfuse::apps {

std::vector<std::string> rejection_warnings(
    const std::array<KindSummary, static_cast<std::size_t>(MeasurementKind::kCount)>& kinds) {
  constexpr std::array kWatched = {MeasurementKind::kImu, MeasurementKind::kGnssPosition, MeasurementKind::kGnssVelocity,
                                   MeasurementKind::kGnssHeading};
  std::vector<std::string> out;
  for (const MeasurementKind kind : kWatched) {
    const KindSummary& ks = kinds[static_cast<std::size_t>(kind)];
    std::uint64_t rejected = 0;
    std::string reasons;
    for (const auto& [reason, n] : ks.rejected) {
      if (reason == "not_aligned" || n == 0) continue;
      rejected += n;
      reasons += (reasons.empty() ? "" : ", ") + reason + ": " + std::to_string(n);
    }
    if (ks.decoded == 0 || 2 * rejected <= ks.decoded) continue;
    out.push_back("most " + std::string(to_string(kind)) + " samples were rejected: " + std::to_string(rejected) +
                  " of " + std::to_string(ks.decoded) + " (" + reasons + ")");
  }
  return out;
}

}  // namespace navfuse::apps
