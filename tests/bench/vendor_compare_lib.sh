# Shared by fe_vendor_compare.sh and mip_vendor_compare.sh (sourced, not run): one timed figure per
# parser from the files the stream tools and the vendor drivers print ("median_s S mb_per_s R",
# "frames N", "type T N" per message type or descriptor set).

# run NAME OUT COMMAND...: runs COMMAND into OUT and prints its line of the comparison.
run() {
  local name=$1 out=$2
  shift 2
  "$@" >"$out"
  printf '%-16s %8s MB/s  median %8s s  valid frames %s\n' "$name" \
    "$(awk '$1 == "median_s" {print $4}' "$out")" "$(awk '$1 == "median_s" {print $2}' "$out")" \
    "$(awk '$1 == "frames" {print $2}' "$out")"
}

# types FILE: the "type T N" lines of a run's output.
types() { grep '^type ' "$1"; }
