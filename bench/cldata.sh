#!/usr/bin/env bash
# CLData translation benchmark (issue 10): an ADEM CLData listing of N records (bench/gen_cldata.py,
# generated here, not committed) translated to Sinumerik and to Heidenhain, and its binary form
# (ncc-cld --binary) to Sinumerik; wall time and peak RSS of each `ncc translate` with
# /usr/bin/time, one run each, records per second. A second, smaller size shows how memory grows
# with the file.
#
# usage: bench/cldata.sh [--records N] [--small M]     defaults 1,000,000 and 250,000
# env: NCC, NCC_CLD (binaries), BENCH_DIR (work folder)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ncc=${NCC:-$root/build/utils/ncc}
cld=${NCC_CLD:-$root/build/utils/ncc-cld}
dir=${BENCH_DIR:-/tmp/ncc-bench-cldata}
records=1000000 small=250000
while [ $# -gt 0 ]; do
  case "$1" in
    --records) records=$2; shift 2 ;;
    --small) small=$2; shift 2 ;;
    *) echo "usage: $0 [--records N] [--small M]" >&2; exit 2 ;;
  esac
done
[ -x "$ncc" ] && [ -x "$cld" ] || { echo "bench: build ncc and ncc-cld first" >&2; exit 2; }
mkdir -p "$dir"

# measure NAME RECORDS CMD...: wall seconds, peak RSS, records per second.
measure() {
  local name=$1 n=$2; shift 2
  /usr/bin/time -f "%e %M" -o "$dir/time.txt" "$@" </dev/null >/dev/null 2>"$dir/$name.err" || {
    echo "bench: $name failed:" >&2; tail -5 "$dir/$name.err" >&2; return 1; }
  read -r t r <"$dir/time.txt"
  awk -v name="$name" -v t="$t" -v r="$r" -v n="$n" \
    'BEGIN { printf "  %-34s %8.2f s  %8d KB  %10.0f records/s\n", name, t, r, (t > 0 ? n / t : 0) }'
}

for n in "$small" "$records"; do
  python3 "$root/bench/gen_cldata.py" "$dir/bench-$n.cld" "$n"
  "$cld" --binary "$dir/bench-$n.cld" -o "$dir/bench-$n.bin.cld"
  echo "$n records ($(du -h "$dir/bench-$n.cld" | cut -f1) listing, $(du -h "$dir/bench-$n.bin.cld" | cut -f1) binary):"
  measure "listing-to-sinumerik-$n" "$n" "$ncc" translate "$dir/bench-$n.cld" --to=sinumerik -o "$dir/out-$n.mpf"
  measure "listing-to-heidenhain-$n" "$n" "$ncc" translate "$dir/bench-$n.cld" --to=heidenhain -o "$dir/out-$n.h"
  measure "binary-to-sinumerik-$n" "$n" "$ncc" translate "$dir/bench-$n.bin.cld" --dialect=adem --to=sinumerik -o "$dir/out-$n.bin.mpf"
done
