// Values sorted without holding them all in memory: added values collect in a run of at most
// `run_values`; a full run is sorted and written to a temporary file (spill_file.hpp), and
// sorted() merges the runs (k-way, a min-heap over each run's next value) into one ascending
// stream. Memory: one run while adding; while reading, `block_values` per run.
//
// The sequence read back is exactly std::sort of all the values (the merge of sorted runs is a
// sorted permutation, and equal values are interchangeable), so a figure computed from it
// (a nearest-rank percentile, a sum taken in ascending order) equals the one computed from an
// in-memory sort. Values must be totally ordered (no NaN).
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <queue>
#include <vector>

#include "apps/common/spill_file.hpp"

namespace navfuse::apps {

template <class T>
class ExternalSort {
 public:
  // 8192 values: 64 kB a sorter of doubles; a 24-hour 200 Hz series is ~2,100 runs.
  explicit ExternalSort(std::size_t run_values = 8192) : run_values_(run_values < 1 ? 1 : run_values) {}

  void add(T value) {
    run_.push_back(value);
    if (run_.size() >= run_values_) spill_run();
  }
  std::size_t size() const { return runs_.size() * run_values_ + run_.size(); }
  bool empty() const { return size() == 0; }

  // The values in ascending order. The sorter must outlive the reader and not change meanwhile.
  class Reader {
   public:
    bool next(T& out) {
      if (heap_.empty()) return false;
      const Head head = heap_.top();
      heap_.pop();
      out = head.value;
      if (T v; sources_[head.source].next(v, tail_)) heap_.push({v, head.source});
      return true;
    }

   private:
    friend class ExternalSort;
    // One run: its values in the file through a reader, or the unspilled tail (the reader's own
    // sorted copy, passed in so that a moved reader stays valid).
    struct Source {
      typename SpillFile<T>::Reader file;
      std::size_t left = 0;
      bool is_tail = false;
      std::size_t tail_pos = 0;
      bool next(T& v, const std::vector<T>& tail) {
        if (is_tail) {
          if (tail_pos >= tail.size()) return false;
          v = tail[tail_pos++];
          return true;
        }
        if (left == 0) return false;
        --left;
        return file.next(v);
      }
    };
    struct Head {
      T value;
      std::size_t source;
      bool operator>(const Head& o) const { return value > o.value; }
    };
    Reader(const ExternalSort& sorter, std::size_t block_values) : tail_(sorter.run_) {
      std::sort(tail_.begin(), tail_.end());
      for (std::size_t first : sorter.runs_) {
        const std::size_t n = std::min(sorter.run_values_, block_values);
        sources_.push_back({sorter.spill_.reader(first, n), sorter.run_values_, false, 0});
      }
      sources_.push_back({sorter.spill_.reader(), 0, true, 0});
      for (std::size_t i = 0; i < sources_.size(); ++i) {
        if (T v; sources_[i].next(v, tail_)) heap_.push({v, i});
      }
    }
    std::vector<T> tail_;
    std::vector<Source> sources_;
    std::priority_queue<Head, std::vector<Head>, std::greater<Head>> heap_;
  };
  // `block_values`: values read from the file at a time per run.
  Reader sorted(std::size_t block_values = 256) const { return Reader(*this, block_values < 1 ? 1 : block_values); }

 private:
  void spill_run() {
    std::sort(run_.begin(), run_.end());
    runs_.push_back(spill_.size());
    for (const T& v : run_) spill_.push_back(v);
    run_.clear();
  }

  std::size_t run_values_;
  std::vector<T> run_;
  std::vector<std::size_t> runs_;  // first index of each spilled run in spill_
  SpillFile<T> spill_{4096};
};

}  // namespace navfuse::apps
