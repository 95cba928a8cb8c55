#!/bin/sh
# ctest driver for the fusion-engine-client compatibility check: creates (once) a virtualenv in
# the build tree with the PyPI package, writes a navfuse stream and checks it. Any failure,
# including pip failing for lack of network, fails the test.
#   usage: python_compat.sh WRITER_EXE CHECK_SCRIPT VENV_DIR WORK_DIR
set -eu
writer=$1 check=$2 venv=$3 work=$4
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c "import fusion_engine_client" 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet fusion-engine-client
fi
mkdir -p "$work"
"$writer" "$work/navfuse_outputs.p1log" "$work/expected.json"
# Its bundled leap-second table has expired; the client refuses to load without this.
GPSTIME_ALLOW_EXPIRED=1 "$venv/bin/python" "$check" "$work/navfuse_outputs.p1log" "$work/expected.json"
