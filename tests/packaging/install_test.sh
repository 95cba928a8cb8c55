#!/usr/bin/env bash
# `cmake --install` into a temporary prefix: what lands where, that the installed binary runs
# with the installed config, that the unit names the installed paths and restarts on failure,
# that a second install keeps the operator's edits; with `verify`, `systemd-analyze verify` on
# the installed unit (exit 77, skipped, where systemd-analyze is not installed).
# Usage: install_test.sh BUILD_DIR SOURCE_DIR files|verify
set -euo pipefail
BUILD=${1:?build dir}
SRC=${2:?source dir}
MODE=${3:?files or verify}
PREFIX=$(mktemp -d "${TMPDIR:-/tmp}/navfuse_install_${MODE}_XXXXXX")
trap 'rm -rf "$PREFIX"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

if [ "$MODE" = verify ] && ! command -v systemd-analyze > /dev/null; then
  echo "systemd-analyze not installed: unit not verified (skipped)"
  exit 77
fi

cmake --install "$BUILD" --prefix "$PREFIX" > "$PREFIX.log" 2>&1 || { cat "$PREFIX.log"; fail "cmake --install"; }
rm -f "$PREFIX.log"
UNIT=$PREFIX/lib/systemd/system/navfuse.service

if [ "$MODE" = verify ]; then
  systemd-analyze verify "$UNIT" || fail "systemd-analyze verify $UNIT"
  echo "PASS: systemd-analyze verify"
  exit 0
fi

for f in bin/navfuse etc/navfuse/navfuse.yaml etc/navfuse/navfuse.env lib/systemd/system/navfuse.service \
         share/navfuse/config/vn300.yaml share/navfuse/config/cv7.yaml \
         share/navfuse/config/fusionengine.yaml share/navfuse/config/um220.yaml \
         share/navfuse/python/navfuse/pose_t.py share/navfuse/python/navfuse/__init__.py \
         share/navfuse/examples/pose_subscriber.py; do
  [ -f "$PREFIX/$f" ] || fail "$f not installed"
done
[ -x "$PREFIX/bin/navfuse" ] || fail "bin/navfuse not executable"
cmp -s "$SRC/data/config/vn300.yaml" "$PREFIX/etc/navfuse/navfuse.yaml" || fail "navfuse.yaml is not the VN-300 example"

# The unit runs the installed binary with the installed config and environment file.
grep -qx "ExecStart=$PREFIX/bin/navfuse run --config $PREFIX/etc/navfuse/navfuse.yaml \$NAVFUSE_ARGS" "$UNIT" \
  || fail "ExecStart does not name the installed paths: $(grep ExecStart "$UNIT")"
grep -qx "EnvironmentFile=$PREFIX/etc/navfuse/navfuse.env" "$UNIT" || fail "EnvironmentFile"
grep -qx "Restart=on-failure" "$UNIT" || fail "Restart=on-failure missing"
grep -qx "LimitRTPRIO=50" "$UNIT" || fail "LimitRTPRIO missing"
grep -qx "LimitMEMLOCK=infinity" "$UNIT" || fail "LimitMEMLOCK missing"
# The priority the service asks for is one the unit's limit grants.
grep -q -- "--rt-priority 50 --lock-memory" "$PREFIX/etc/navfuse/navfuse.env" || fail "navfuse.env options"

# The installed binary with the installed config fuses the demo drive.
"$PREFIX/bin/navfuse" replay --config "$PREFIX/etc/navfuse/navfuse.yaml" "$SRC/data/demo/vn300.vnb" \
  --summary-json "$PREFIX/summary.json" --quiet || fail "installed navfuse replay"
python3 -c 'import json, sys; sys.exit("navigation" not in json.load(open(sys.argv[1]))["run"]["modes_reached"])' \
  "$PREFIX/summary.json" || fail "installed replay never navigated"
# The service's arguments parse: `run` with them refuses only the missing serial device.
NAVFUSE_ARGS=$(sed -n 's/^NAVFUSE_ARGS=//p' "$PREFIX/etc/navfuse/navfuse.env")
# shellcheck disable=SC2086
out=$(timeout 10 "$PREFIX/bin/navfuse" run --config "$PREFIX/etc/navfuse/navfuse.yaml" $NAVFUSE_ARGS 2>&1 || true)
echo "$out" | grep -q "/dev/ttyUSB0" || fail "navfuse run with the service's arguments: $out"

# A second install keeps what the operator edited.
echo "# edited" >> "$PREFIX/etc/navfuse/navfuse.env"
cmake --install "$BUILD" --prefix "$PREFIX" > /dev/null
grep -q "# edited" "$PREFIX/etc/navfuse/navfuse.env" || fail "re-install overwrote navfuse.env"
echo "PASS: install into $PREFIX"
