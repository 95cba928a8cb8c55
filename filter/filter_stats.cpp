#include "filter/filter_stats.hpp"

namespace navfuse::filter {

std::string_view to_string(RejectReason reason) {
  switch (reason) {
    case RejectReason::kNan: return "nan";
    case RejectReason::kNegativeStd: return "negative_std";
    case RejectReason::kInvalid: return "invalid";
    case RejectReason::kTimeBackwards: return "time_backwards";
    case RejectReason::kTimeGap: return "time_gap";
    case RejectReason::kTooLate: return "too_late";
    case RejectReason::kNotAligned: return "not_aligned";
    case RejectReason::kNoFix: return "no_fix";
    case RejectReason::kChi2Gate: return "chi2_gate";
    case RejectReason::kNumerical: return "numerical";
    case RejectReason::kOverflow: return "overflow";
    case RejectReason::kNoReference: return "no_reference";
    case RejectReason::kNoScale: return "no_scale";
    case RejectReason::kBaselineMismatch: return "baseline_mismatch";
    case RejectReason::kMagneticDisturbance: return "magnetic_disturbance";
    case RejectReason::kNoDeclination: return "no_declination";
    case RejectReason::kGnssJump: return "gnss_jump";
    case RejectReason::kCount: break;
  }
  return "unknown";
}

std::uint64_t KindStats::rejected_total() const {
  std::uint64_t n = 0;
  for (auto r : rejected) n += r;
  return n;
}

}  // namespace navfuse::filter
