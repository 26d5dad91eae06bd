#!/usr/bin/env bash
# Benchmarks ncc against LinuxCNC's rs274 (when installed) on the shared benchmark programs.
# Every figure is measured in this run; ratios compare against rs274 measured alongside.
#
# usage: bench/run.sh [--lines N] [--iters N] [--runs K] [--planner-only]
#   defaults: 1,000,000 lines, 1,000,000 iterations, 3 runs (median wall time reported)
#   --planner-only: just the planner rows (planned and unplanned macro_motion runs)
# env: NCC (ncc binary), NCC_SHARED (the shared/ folder), BENCH_DIR (work folder),
#      NCC_BASE (a second ncc binary, e.g. an older build: its planner is measured in the same run)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ncc=${NCC:-$root/build/utils/ncc}
shared=${NCC_SHARED:-$root/../shared}
dir=${BENCH_DIR:-/tmp/ncc-bench}
lines=1000000 iters=1000000 runs=3 planner_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --lines) lines=$2; shift 2 ;;
    --iters) iters=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --planner-only) planner_only=1; shift ;;
    *) echo "usage: $0 [--lines N] [--iters N] [--runs K] [--planner-only]" >&2; exit 2 ;;
  esac
done
[ -x "$ncc" ] || { echo "bench: build ncc first (utils/bootstrap.sh)" >&2; exit 2; }
mkdir -p "$dir"
python3 "$shared/bench/gen_bench.py" "$dir" --lines "$lines" --iters "$iters"
home=$(mktemp -d)
have_rs274=0
command -v rs274 >/dev/null && have_rs274=1

# measure NAME CMD...: median wall seconds over $runs runs, the peak RSS (KB) of the last run and
# the median CPU seconds (user + system: steadier than wall time when other jobs share the cores).
measure() {
  local name=$1; shift
  local times=() cpus=() rss=0
  for _ in $(seq "$runs"); do
    /usr/bin/time -f "%e %M %U %S" -o "$dir/time.txt" env HOME="$home" "$@" </dev/null >/dev/null 2>"$dir/$name.err" || {
      echo "bench: $name failed:" >&2; cat "$dir/$name.err" >&2; return 1; }
    read -r t r u k <"$dir/time.txt"
    times+=("$t"); rss=$r
    cpus+=("$(awk -v u="$u" -v k="$k" 'BEGIN { print u + k }')")
  done
  local med cpu
  med=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  cpu=$(printf '%s\n' "${cpus[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  printf '%s %s %s %s\n' "$name" "$med" "$rss" "$cpu" >>"$dir/results.txt"
  printf '  %-28s %8.3f s  %8d KB  (cpu %.3f s)\n' "$name" "$med" "$rss" "$cpu"
}

get() { awk -v n="$1" '$1==n {print $2}' "$dir/results.txt"; }
getcpu() { awk -v n="$1" '$1==n {print $4}' "$dir/results.txt"; }
# ratio A B: A's time / B's, wall, then CPU (user + system: steadier when other jobs share the cores).
ratio() { awk -v a="$(get "$1")" -v b="$(get "$2")" -v c="$(getcpu "$1")" -v d="$(getcpu "$2")" \
  'BEGIN { if (b > 0) printf "%.1fx", a / b; else printf "n/a"; if (d > 0) printf " (cpu %.1fx)", c / d }'; }

# The planner's rate: macro_motion has one G1 per iteration; the planned run (summary) minus the
# same run without planning (-q) is the planner's time (CPU seconds, see measure).
planner_rows() {  # BINARY PREFIX
  measure "$2-macro-unplanned-jit" "$1" run "$dir/macro_motion.nc" --engine=jit -q
  measure "$2-macro-planned-jit" "$1" run "$dir/macro_motion.nc" --engine=jit
}
planner_rate() {  # PREFIX: M segments/s
  awk -v p="$(getcpu "$1-macro-planned-jit")" -v u="$(getcpu "$1-macro-unplanned-jit")" -v n="$iters" \
    'BEGIN { if (p > u) printf "%.2f", n / (p - u) / 1e6; else print "inf" }'
}

: >"$dir/results.txt"
echo "ncc: $("$ncc" --version); programs in $dir; median of $runs runs"
if [ $planner_only = 1 ]; then
  planner_rows "$ncc" ncc
  [ -n "${NCC_BASE:-}" ] && planner_rows "$NCC_BASE" base
  echo "planner: $(planner_rate ncc) M segments/s (target >= 2 M/s)"
  if [ -n "${NCC_BASE:-}" ]; then
    echo "planner of NCC_BASE: $(planner_rate base) M segments/s"
    awk -v a="$(planner_rate ncc)" -v b="$(planner_rate base)" 'BEGIN { if (b > 0) printf "ratio ncc / NCC_BASE: %.1fx\n", a / b }'
  fi
  rm -rf "$home"
  exit 0
fi
# Like rs274, these interpret to canonical commands only (-q: no trajectory planning).
measure ncc-flat-canon        "$ncc" run "$dir/flat_moves.ngc" --trace=canon -o "$dir/flat.ncc.canon" -q
measure ncc-macro-motion-jit  "$ncc" run "$dir/macro_motion.nc" --engine=jit --trace=canon -o "$dir/macro.ncc.canon" -q
measure ncc-macro-motion-eval "$ncc" run "$dir/macro_motion.nc" --engine=eval --trace=canon -o "$dir/macro.ncc.eval.canon" -q
measure ncc-macro-compute-jit "$ncc" run "$dir/macro_compute.nc" --engine=jit -q
measure ncc-macro-compute-eval "$ncc" run "$dir/macro_compute.nc" --engine=eval -q
# The Sinumerik twins (frontend/sinumerik): the same loop, the same trace as the .nc one.
measure ncc-sin-motion-jit    "$ncc" run "$dir/macro_motion.mpf" --engine=jit --trace=canon -o "$dir/macro.sin.canon" -q
measure ncc-sin-compute-jit   "$ncc" run "$dir/macro_compute.mpf" --engine=jit -q
"$ncc" canon-diff --level=machine "$dir/macro.ncc.canon" "$dir/macro.sin.canon" && echo "macro_motion.mpf trace = macro_motion.nc trace: yes" || echo "macro_motion.mpf trace = macro_motion.nc trace: NO"
# The full run: trajectory planning for the summary (cycle time), no trace. rs274 does no planning.
measure ncc-flat-planned      "$ncc" run "$dir/flat_moves.ngc"
planner_rows "$ncc" ncc
echo "planner: $(planner_rate ncc) M segments/s (target >= 2 M/s)"
# A small program (55 lines) end to end (start-up, compilation with the JIT, run), as rs274 runs it.
small=$(dirname "$0")/../test/lit/oracle/param_computed.ngc
# Each small row is 20 runs in a row (one run is below the timer's 10 ms resolution).
small20=$dir/small20.sh
printf '%s\n' 'for i in $(seq 20); do "$@" || exit 1; done' >"$small20"
measure ncc-small-eval        sh "$small20" "$ncc" run "$small" --trace=canon -o "$dir/small.ncc.canon" -q
measure ncc-small-jit         sh "$small20" "$ncc" run "$small" --engine=jit --trace=canon -o "$dir/small.ncc.jit.canon" -q
if [ $have_rs274 = 1 ]; then
  measure rs274-flat          rs274 -g "$dir/flat_moves.ngc" "$dir/flat.rs274.canon"
  measure rs274-macro-motion  rs274 -g "$dir/macro_motion.ngc" "$dir/macro.rs274.canon"
  measure rs274-macro-compute rs274 -g "$dir/macro_compute.ngc" "$dir/compute.rs274.canon"
  measure rs274-small         sh "$small20" rs274 -g "$small" "$dir/small.rs274.canon"
  echo
  echo "ratios (rs274 time / ncc time, same run):"
  echo "  flat_moves to a canonical trace file:        $(ratio rs274-flat ncc-flat-canon)   (target >= 20x)"
  echo "  macro_motion, jit engine (trace to file):    $(ratio rs274-macro-motion ncc-macro-motion-jit)   (target >= 100x)"
  echo "  macro_motion, eval engine (trace to file):   $(ratio rs274-macro-motion ncc-macro-motion-eval)"
  echo "  macro_compute, jit engine:                   $(ratio rs274-macro-compute ncc-macro-compute-jit)"
  echo "  macro_compute, eval engine:                  $(ratio rs274-macro-compute ncc-macro-compute-eval)"
  echo "  small program end to end, eval engine:       $(ratio rs274-small ncc-small-eval)   (target: ncc / rs274 <= 1.0, i.e. >= 1.0x)"
  echo "  small program end to end, jit engine:        $(ratio rs274-small ncc-small-jit)   (target >= 1.0x)"
  echo "traces agree at machine level:"
  "$ncc" canon-diff --level=machine "$dir/flat.rs274.canon" "$dir/flat.ncc.canon" && echo "  flat_moves: yes" || echo "  flat_moves: NO"
  "$ncc" canon-diff --level=machine "$dir/macro.rs274.canon" "$dir/macro.ncc.canon" && echo "  macro_motion (jit): yes" || echo "  macro_motion (jit): NO"
else
  echo "(rs274 not installed: apt-get install linuxcnc-uspace for the comparison)"
fi
echo "peak RSS of ncc on flat_moves with a trace: $(awk '$1=="ncc-flat-canon" {print $3}' "$dir/results.txt") KB (target <= 49152 KB)"
echo "macro_compute, eval time / jit time:        $(ratio ncc-macro-compute-eval ncc-macro-compute-jit)   (target >= 10x)"
rm -rf "$home"
