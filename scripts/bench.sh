#!/usr/bin/env bash
# Runs every Google Benchmark program with repetitions and prints the medians.
set -euo pipefail
build=${1:-build/release}
status=0
for b in $(find "$build/tests/bench" -maxdepth 2 -type f -executable -name '*bench*' | sort); do
  echo "== $(basename "$b")"
  "$b" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
       --benchmark_min_time=0.2 | grep -E 'median|^-|Benchmark' || status=1
done
exit $status
