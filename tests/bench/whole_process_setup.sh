# Sourced by the whole-process benchmark scripts (replay_throughput.sh, smooth_throughput.sh,
# kfgins_compare.sh):
# their arguments [BUILD_DIR] [RUNS], the navfuse binary, /usr/bin/time, a scratch folder removed
# on exit. Set BENCH_NAME and DEFAULT_RUNS before sourcing; gives NAVFUSE, RUNS and work.
set -euo pipefail
BUILD_DIR=${1:-build/release}
RUNS=${2:-$DEFAULT_RUNS}
NAVFUSE="$BUILD_DIR/apps/navfuse"
[ -x "$NAVFUSE" ] || { echo "$BENCH_NAME: $NAVFUSE not found (build first)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "$BENCH_NAME: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
