#!/usr/bin/env bash
# First contact with the command line: every command's --help ends with worked examples and has
# -q,--quiet; the examples of the commands that need no device or LCM (decode, replay, sim, bench)
# run as written, from a folder with the sources' data/ in it.
# Usage: cli_help_test.sh NAVFUSE SOURCE_DIR
set -euo pipefail
BIN=${1:?navfuse binary}
SRC=${2:?source dir}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/navfuse_cli_help_XXXXXX")
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
ln -s "$SRC/data" "$TMP/data"
# What replay's second example replays: a recording made by run (its own example records too).
(cd "$TMP" && "$BIN" run --config data/demo/vn300.yaml data/demo/vn300.vnb --record rec --quiet 2> /dev/null) \
  || fail "navfuse run --record"

for cmd in decode replay run bench aid sim config; do
  help=$("$BIN" "$cmd" --help)
  echo "$help" | grep -q -- "-q,--quiet" || fail "$cmd --help: no -q,--quiet"
  # The examples are the end of the help: "Examples:", then pairs of "# what" / "navfuse CMD ...".
  tail_block=$(echo "$help" | sed -n '/^Examples:$/,$p')
  [ -n "$tail_block" ] || fail "$cmd --help does not end with Examples:"
  n=$(echo "$tail_block" | grep -c "^  navfuse $cmd " || true)
  [ "$n" -ge 1 ] && [ "$n" -le 2 ] || fail "$cmd --help: $n examples (want 1 or 2)"
  [ "$(echo "$help" | tail -n 1 | grep -c "^  navfuse ")" -eq 1 ] || fail "$cmd --help does not end with an example"
  case $cmd in run | aid) continue ;; esac  # need a device or an LCM listener
  while IFS= read -r line; do
    echo "== $line"
    (set +o pipefail; cd "$TMP" && navfuse() { "$BIN" "$@"; } && eval "${line#  }") > "$TMP/out.txt" 2>&1 \
      || { cat "$TMP/out.txt"; fail "example failed: $line"; }
  done < <(echo "$tail_block" | grep "^  navfuse $cmd ")
done
echo "PASS"
