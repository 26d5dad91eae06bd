#!/bin/sh
# Re-records the rs274 trace of every oracle program (test/lit/oracle/*.ngc).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
dir=$here/../../test/lit/oracle
for prog in "$dir"/*.ngc; do
  name=$(basename "$prog" .ngc)
  "$here/record.sh" "$prog" "$dir/Inputs/$name.rs274"
  echo "recorded $name"
done
