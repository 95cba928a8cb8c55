#!/usr/bin/env bash
# Installs the Debian packages navfuse needs, only those missing (idempotent). Uses sudo only when
# not root. Called by `make deps` (and so by `make test`, `make demo`, `make sanitize`).
set -euo pipefail

packages=(
  cmake ninja-build g++ make pkg-config ccache time   # time: tests/bench/replay_throughput.sh
  clang libclang-rt-14-dev            # libFuzzer targets and the sanitizer build
  libeigen3-dev libgeographiclib-dev libceres-dev
  liblcm-dev liblcm-bin libglib2.0-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev
  proj-data                           # /usr/share/proj/egm96_15.gtx, the EGM96 geoid grid
  python3 python3-venv python3-pip    # FusionEngine client compatibility test
  python3-matplotlib chromium         # navfuse bench: report plots; headless check that report.html renders
)
if [ -n "${NAVFUSE_EXTRA_PACKAGES:-}" ]; then
  read -r -a extra <<< "${NAVFUSE_EXTRA_PACKAGES}"
  packages+=("${extra[@]}")
fi

# Installed where the distribution packages them (Debian 12 does not): LCM's Python module, for
# examples/python/pose_subscriber.py and its test (which is skipped without it).
optional=(python3-lcm)
for p in "${optional[@]}"; do
  if apt-cache show "$p" > /dev/null 2>&1; then packages+=("$p"); fi
done

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "navfuse: installing missing Debian packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
