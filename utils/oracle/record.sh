#!/bin/sh
# Records LinuxCNC rs274's canonical trace for ncc's oracle tests.
#   record.sh PROG.ngc OUT.rs274 [TOOLS.txt]
# Runs rs274 in isolation: private HOME (it truncates $HOME/.tool.mmap), no .var file (all offsets
# zero), -g and </dev/null (no start-up menu), the output-file argument (buffered). The tool table
# is generated from TOOLS.txt (ncc's mm tool data, `T<n> length <mm> radius <mm>` per line)
# converted to inches, because the standalone rs274 reads tool tables in inches.
set -eu
prog=$1
case $2 in /*) out=$2 ;; *) out=$(pwd)/$2 ;; esac
here=$(cd "$(dirname "$0")" && pwd)
tools=${3:-$here/../../test/lit/oracle/Inputs/tools.txt}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
awk '
  /^[ \t]*(#|$)/ { next }
  {
    t = $1; sub(/^[Tt]/, "", t); len = 0; rad = 0
    for (i = 2; i < NF; i += 2) {
      if ($i == "length") len = $(i + 1)
      if ($i == "radius") rad = $(i + 1)
    }
    printf "T%d P%d D%.6f Z%+.6f\n", t, t, 2 * rad / 25.4, len / 25.4
  }' "$tools" >"$tmp/tool.tbl"
cd "$(dirname "$prog")"
set +e
HOME="$tmp" rs274 -g -t "$tmp/tool.tbl" -v "$tmp/p.var" "$(basename "$prog")" "$tmp/out" </dev/null >"$tmp/stdout" 2>"$tmp/stderr"
rc=$?
set -e
if [ $rc -ne 0 ]; then
  echo "rs274 failed (rc $rc) on $prog:" >&2
  cat "$tmp/stderr" >&2
  exit 1
fi
cp "$tmp/out" "$out"
