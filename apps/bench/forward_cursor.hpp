// A time-ordered stream read forward to answer lookups at increasing times with two items in
// memory: the last item before the time asked (or at it) and the one after. The solution-track
// interpolator, the phase labels and the GNSS-outage test of `navfuse bench` all look up their
// series this way at the sampled solution's times, so none holds its series in memory.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

namespace navfuse::apps::bench {

// `Reader::next(T&)` gives the items in non-decreasing time order; `TimeOf(const T&)` their time.
template <class Reader, class T, class TimeOf>
class ForwardCursor {
 public:
  ForwardCursor(Reader reader, TimeOf time_of) : reader_(std::move(reader)), time_of_(time_of) { pull(); }

  // Moves on while the next item is before `time_ns` (`inclusive`: at or before it).
  void advance(std::int64_t time_ns, bool inclusive) {
    while (next_ && (time_of_(*next_) < time_ns || (inclusive && time_of_(*next_) == time_ns))) {
      last_ = std::move(next_);
      pull();
    }
  }
  const std::optional<T>& last() const { return last_; }  // the last item passed (none yet: nullopt)
  const std::optional<T>& next() const { return next_; }  // the first item not passed (end: nullopt)

 private:
  void pull() {
    if (T item; reader_.next(item)) {
      next_ = std::move(item);
    } else {
      next_.reset();
    }
  }

  Reader reader_;
  TimeOf time_of_;
  std::optional<T> last_, next_;
};

}  // namespace navfuse::apps::bench
