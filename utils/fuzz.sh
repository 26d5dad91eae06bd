#!/usr/bin/env bash
# Builds the libFuzzer targets (test/fuzz) with clang-19 into ./build-fuzz and runs each for
# SECONDS (default 60), starting from the seed corpus test/fuzz/corpus/<target>, mutating
# with the words of test/fuzz/<target>.dict.
# Usage: utils/fuzz.sh [SECONDS] [TARGET...]
#   (targets: iso ir machine motion heidenhain sinumerik apt adem; default all)
# New inputs go to build-fuzz/corpus/<target> (not the repository); findings (crash-*, leak-*,
# timeout-*, oom-*) to build-fuzz/findings/<target>/. Reproduce one with
#   build-fuzz/test/fuzz/fuzz-<target> FILE
# A fixed finding belongs in the seed corpus plus a unit or lit test (README "Tests").
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(iso ir machine motion heidenhain sinumerik apt adem)

utils/install-missing.sh clang-19 libclang-rt-19-dev

if [ ! -f build-fuzz/build.ninja ]; then
  # -O1 and line tables only, as OSS-Fuzz builds: smaller objects than -O2 -g, the reports
  # still name file and line.
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
        -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
        -DCMAKE_C_COMPILER=clang-19 -DCMAKE_CXX_COMPILER=clang++-19 -DNCC_FUZZ=ON
fi
nice ninja -C build-fuzz -j2 "${targets[@]/#/fuzz-}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
summary=()
total_findings=0
for t in "${targets[@]}"; do
  work=build-fuzz/corpus/$t findings=build-fuzz/findings/$t log=build-fuzz/fuzz-$t.log
  mkdir -p "$work" "$findings"
  before=$(ls "$findings" | wc -l)
  echo "fuzz: $t for ${seconds}s (log $log)"
  # Stops at the first finding; rerunning continues from the grown corpus.
  build-fuzz/test/fuzz/fuzz-$t "$work" "test/fuzz/corpus/$t" -max_total_time="$seconds" \
      -dict="test/fuzz/$t.dict" -max_len=4096 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$findings/" >"$log" 2>&1 || true
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  new=$(( $(ls "$findings" | wc -l) - before ))
  total_findings=$((total_findings + new))
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 || true)
  summary+=("$(printf '%-8s %10s executions  %s  %d new finding(s)' "$t" "$execs" "$cov" "$new")")
  if [ "$new" -gt 0 ]; then
    grep -m1 -E 'ERROR: (AddressSanitizer|libFuzzer|LeakSanitizer)|runtime error|fuzz invariant' "$log" || true
    ls -t "$findings" | head -n "$new" | sed "s|^|  $findings/|"
  fi
done
echo "fuzz summary (${seconds}s per target):"
printf '  %s\n' "${summary[@]}"
[ "$total_findings" -eq 0 ]
