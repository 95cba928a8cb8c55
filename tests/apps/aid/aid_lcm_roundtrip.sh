#!/usr/bin/env bash
# `navfuse aid heading` published over real LCM arrives with its values at a subscriber.
set -euo pipefail
navfuse=$1
listen=$2
url="udpm://239.255.76.67:7711?ttl=0"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
"$listen" "$url" 5000 > "$out" &
pid=$!
for _ in $(seq 50); do grep -q ready "$out" && break; sleep 0.1; done
# Publish a few times: a multicast datagram sent before the subscriber joined would be lost.
for _ in 1 2 3; do
  "$navfuse" aid heading 123.5 --std 1.5 --time-gps-s 1400000000.25 --lcm "$url"
  sleep 0.2
  grep -q heading_deg "$out" && break
done
wait "$pid"
grep -q "heading_deg=123.500 std_deg=1.500 valid=1 time_gps_ns=1400000000250000000" "$out"
