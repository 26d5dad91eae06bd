#!/usr/bin/env bash
# Benchmarks ncc against LinuxCNC's rs274 (when installed) on the shared benchmark programs.
# Every figure is measured in this run; ratios compare against rs274 measured alongside.
#
# usage: bench/run.sh [--lines N] [--iters N] [--runs K]
#   defaults: 1,000,000 lines, 1,000,000 iterations, 3 runs (median wall time reported)
# env: NCC (ncc binary), NCC_SHARED (the shared/ folder), BENCH_DIR (work folder)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ncc=${NCC:-$root/build/utils/ncc}
shared=${NCC_SHARED:-$root/../shared}
dir=${BENCH_DIR:-/tmp/ncc-bench}
lines=1000000 iters=1000000 runs=3
while [ $# -gt 0 ]; do
  case "$1" in
    --lines) lines=$2; shift 2 ;;
    --iters) iters=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    *) echo "usage: $0 [--lines N] [--iters N] [--runs K]" >&2; exit 2 ;;
  esac
done
[ -x "$ncc" ] || { echo "bench: build ncc first (utils/bootstrap.sh)" >&2; exit 2; }
mkdir -p "$dir"
python3 "$shared/bench/gen_bench.py" "$dir" --lines "$lines" --iters "$iters"
home=$(mktemp -d)
have_rs274=0
command -v rs274 >/dev/null && have_rs274=1

# measure NAME CMD...: median wall seconds over $runs runs and the peak RSS (KB) of the last.
measure() {
  local name=$1; shift
  local times=() rss=0
  for _ in $(seq "$runs"); do
    /usr/bin/time -f "%e %M" -o "$dir/time.txt" env HOME="$home" "$@" </dev/null >/dev/null 2>"$dir/$name.err" || {
      echo "bench: $name failed:" >&2; cat "$dir/$name.err" >&2; return 1; }
    read -r t r <"$dir/time.txt"
    times+=("$t"); rss=$r
  done
  local med
  med=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  printf '%s %s %s\n' "$name" "$med" "$rss" >>"$dir/results.txt"
  printf '  %-28s %8.3f s  %8d KB\n' "$name" "$med" "$rss"
}

: >"$dir/results.txt"
echo "ncc: $("$ncc" --version); programs in $dir; median of $runs runs"
# Like rs274, these interpret to canonical commands only (-q: no trajectory planning).
measure ncc-flat-canon        "$ncc" run "$dir/flat_moves.ngc" --trace=canon -o "$dir/flat.ncc.canon" -q
measure ncc-macro-motion-jit  "$ncc" run "$dir/macro_motion.nc" --engine=jit --trace=canon -o "$dir/macro.ncc.canon" -q
measure ncc-macro-motion-eval "$ncc" run "$dir/macro_motion.nc" --engine=eval --trace=canon -o "$dir/macro.ncc.eval.canon" -q
measure ncc-macro-compute-jit "$ncc" run "$dir/macro_compute.nc" --engine=jit -q
measure ncc-macro-compute-eval "$ncc" run "$dir/macro_compute.nc" --engine=eval -q
# The full run: trajectory planning for the summary (cycle time), no trace. rs274 does no planning.
measure ncc-flat-planned      "$ncc" run "$dir/flat_moves.ngc"
measure ncc-macro-planned-jit "$ncc" run "$dir/macro_motion.nc" --engine=jit
if [ $have_rs274 = 1 ]; then
  measure rs274-flat          rs274 -g "$dir/flat_moves.ngc" "$dir/flat.rs274.canon"
  measure rs274-macro-motion  rs274 -g "$dir/macro_motion.ngc" "$dir/macro.rs274.canon"
  measure rs274-macro-compute rs274 -g "$dir/macro_compute.ngc" "$dir/compute.rs274.canon"
  get() { awk -v n="$1" '$1==n {print $2}' "$dir/results.txt"; }
  ratio() { awk -v a="$(get "$1")" -v b="$(get "$2")" 'BEGIN { if (b > 0) printf "%.1fx", a / b; else print "n/a" }'; }
  echo
  echo "ratios (rs274 time / ncc time, same run):"
  echo "  flat_moves to a canonical trace file:        $(ratio rs274-flat ncc-flat-canon)   (target >= 10x)"
  echo "  macro_motion, jit engine (trace to file):    $(ratio rs274-macro-motion ncc-macro-motion-jit)   (target >= 20x)"
  echo "  macro_motion, eval engine (trace to file):   $(ratio rs274-macro-motion ncc-macro-motion-eval)"
  echo "  macro_compute, jit engine:                   $(ratio rs274-macro-compute ncc-macro-compute-jit)"
  echo "  macro_compute, eval engine:                  $(ratio rs274-macro-compute ncc-macro-compute-eval)"
  echo "traces agree at machine level:"
  "$ncc" canon-diff --level=machine "$dir/flat.rs274.canon" "$dir/flat.ncc.canon" && echo "  flat_moves: yes" || echo "  flat_moves: NO"
  "$ncc" canon-diff --level=machine "$dir/macro.rs274.canon" "$dir/macro.ncc.canon" && echo "  macro_motion (jit): yes" || echo "  macro_motion (jit): NO"
else
  echo "(rs274 not installed: apt-get install linuxcnc-uspace for the comparison)"
fi
echo "peak RSS of ncc on flat_moves with a trace: $(awk '$1=="ncc-flat-canon" {print $3}' "$dir/results.txt") KB (target <= 131072 KB)"
rm -rf "$home"
