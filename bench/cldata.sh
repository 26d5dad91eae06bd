#!/usr/bin/env bash
# CLData benchmark (issue 10): an ADEM CLData listing of N records (bench/gen_cldata.py,
# generated here, not committed) translated to Sinumerik and to Heidenhain, its binary form
# (ncc-cld --binary) to Sinumerik, and the listing run to a canonical trace; wall time and peak
# RSS of each command with /usr/bin/time (wall and CPU time), one run each, records per second; then an APT CL file of
# the same number of records (bench/gen_apt.py) translated to Sinumerik. A second, smaller
# size shows how memory grows with the file. With NCC_BEFORE (another build's ncc) each command
# is run with that binary too, right before this one's, and the ratios are printed: before and
# after in the same run, under the same load.
#
# usage: bench/cldata.sh [--records N] [--small M]     defaults 1,000,000 and 100,000
# env: NCC, NCC_CLD (binaries), NCC_BEFORE (a build to compare with), BENCH_DIR (work folder)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ncc=${NCC:-$root/build/utils/ncc}
cld=${NCC_CLD:-$root/build/utils/ncc-cld}
before=${NCC_BEFORE:-}
dir=${BENCH_DIR:-/tmp/ncc-bench-cldata}
records=1000000 small=100000
while [ $# -gt 0 ]; do
  case "$1" in
    --records) records=$2; shift 2 ;;
    --small) small=$2; shift 2 ;;
    *) echo "usage: $0 [--records N] [--small M]" >&2; exit 2 ;;
  esac
done
[ -x "$ncc" ] && [ -x "$cld" ] || { echo "bench: build ncc and ncc-cld first" >&2; exit 2; }
[ -z "$before" ] || [ -x "$before" ] || { echo "bench: NCC_BEFORE '$before' is not a program" >&2; exit 2; }
mkdir -p "$dir"

# run NAME RECORDS BINARY ARGS...: one timed run; sets t (wall s), c (CPU s: user + system) and
# r (peak RSS KB). On a machine shared beyond its cores the wall time is mostly waiting: the CPU
# time is the steadier measure, and records per CPU second what an idle core would give.
run() {
  local name=$1 n=$2; shift 2
  /usr/bin/time -f "%e %U %S %M" -o "$dir/time.txt" "$@" </dev/null >/dev/null 2>"$dir/$name.err" || {
    echo "bench: $name failed:" >&2; tail -5 "$dir/$name.err" >&2; return 1; }
  local user sys
  read -r t user sys r <"$dir/time.txt"
  c=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
}
# report NAME WHEN WALL CPU RSS RECORDS: one line of the table.
report() {
  awk -v name="$1" -v when="$2" -v t="$3" -v c="$4" -v r="$5" -v n="$6" \
    'BEGIN { printf "  %-30s %-6s %8.2f s wall %8.2f s CPU %8d KB %10.0f records/s %10.0f records/CPU s\n",
             name, when, t, c, r, (t > 0 ? n / t : 0), (c > 0 ? n / c : 0) }'
}
# measure NAME RECORDS OUT ARGS...: this build (and NCC_BEFORE's first): wall and CPU time, peak
# RSS, records/s, written to OUT (NCC_BEFORE's to OUT.before, which must be the same bytes).
measure() {
  local name=$1 n=$2 out=$3; shift 3
  if [ -n "$before" ]; then
    run "$name.before" "$n" "$before" "$@" -o "$out.before"
    local bt=$t bc=$c br=$r
    report "$name" before "$bt" "$bc" "$br" "$n"
  fi
  run "$name" "$n" "$ncc" "$@" -o "$out"
  report "$name" now "$t" "$c" "$r" "$n"
  if [ -n "$before" ]; then
    awk -v t="$t" -v c="$c" -v r="$r" -v bt="$bt" -v bc="$bc" -v br="$br" \
      'BEGIN { printf "  %-30s ratio  %8.1fx wall, %6.1fx CPU, %6.1fx less memory\n", "", (t > 0 ? bt / t : 0),
               (c > 0 ? bc / c : 0), (r > 0 ? br / r : 0) }'
    cmp -s "$out" "$out.before" || { echo "bench: $name: the output differs from NCC_BEFORE's" >&2; return 1; }
    rm -f "$out.before"
  fi
}

for n in "$small" "$records"; do
  python3 "$root/bench/gen_cldata.py" "$dir/bench-$n.cld" "$n"
  "$cld" --binary "$dir/bench-$n.cld" -o "$dir/bench-$n.bin.cld"
  echo "$n records ($(du -h "$dir/bench-$n.cld" | cut -f1) listing, $(du -h "$dir/bench-$n.bin.cld" | cut -f1) binary):"
  measure "listing-to-sinumerik-$n" "$n" "$dir/out-$n.mpf" translate "$dir/bench-$n.cld" --to=sinumerik
  measure "listing-to-heidenhain-$n" "$n" "$dir/out-$n.h" translate "$dir/bench-$n.cld" --to=heidenhain
  measure "binary-to-sinumerik-$n" "$n" "$dir/out-$n.bin.mpf" translate "$dir/bench-$n.bin.cld" --dialect=adem --to=sinumerik
  measure "listing-run-canon-trace-$n" "$n" "$dir/out-$n.canon" run "$dir/bench-$n.cld" --trace=canon
  python3 "$root/bench/gen_apt.py" "$dir/bench-$n.apt" "$n"
  measure "apt-to-sinumerik-$n" "$n" "$dir/out-$n.apt.mpf" translate "$dir/bench-$n.apt" --to=sinumerik
done
