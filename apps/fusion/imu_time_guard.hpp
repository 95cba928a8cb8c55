// One IMU sample with a wild timestamp must not end navigation (issue 15: a checksum-valid
// UM220 GYOACC dated a year ahead made every later sample "time_backwards"; a MIP packet a day
// ahead did the same). A jump forward by more than the filter's largest IMU gap is either a real
// gap in the data or one bad timestamp; the next sample tells which. So the sample after such a
// jump is held back: if the next one continues from it, the jump was real and both go to the
// filter (which restarts across the gap as before); if the next one continues from before the
// jump, the held sample alone was wrong and is rejected ("time_jump"). Cost: a real gap is
// confirmed one sample late. Samples going backwards are left to the filter ("time_backwards").
#pragma once

#include <cstdint>

namespace navfuse::apps {

class ImuTimeGuard {
 public:
  struct Verdict {
    bool reject_held = false;   // the held sample was a lone wild timestamp: reject it
    bool release_held = false;  // the held sample began a real new stretch: fuse it first
    bool hold = false;          // hold this sample back (else fuse it now)
  };

  explicit ImuTimeGuard(std::int64_t max_gap_ns) : max_gap_ns_(max_gap_ns) {}

  Verdict check(std::int64_t t_ns) {
    Verdict v;
    if (holding_) {
      holding_ = false;
      if (t_ns > held_ns_ && t_ns - held_ns_ <= max_gap_ns_) {
        v.release_held = true;
        last_ns_ = t_ns;
        return v;
      }
      v.reject_held = true;
    }
    if (!have_last_) {
      have_last_ = true;
      last_ns_ = t_ns;
    } else if (t_ns > last_ns_ && t_ns - last_ns_ > max_gap_ns_) {
      holding_ = true;
      held_ns_ = t_ns;
      v.hold = true;
    } else if (t_ns > last_ns_) {
      last_ns_ = t_ns;
    }
    return v;
  }
  bool holding() const { return holding_; }
  // The input ended (or was stopped) with a sample held: nothing can confirm it any more.
  void drop_held() { holding_ = false; }

 private:
  std::int64_t max_gap_ns_;
  std::int64_t last_ns_ = 0;
  std::int64_t held_ns_ = 0;
  bool have_last_ = false;
  bool holding_ = false;
};

}  // namespace navfuse::apps
