#!/usr/bin/env bash
# check_programs.sh NCSIM PROGRAMS: `ncsim check` (syntax, structure and semantics on the
# program's machine) must pass on every program folder's program; prints each failure.
set -uo pipefail
ncsim=$1
programs=$2
failures=0
count=0
for dir in "$programs"/*/; do
  name=$(basename "$dir")
  [[ -f $dir/$name.nc ]] || continue
  count=$((count + 1))
  if ! out=$("$ncsim" check "$dir/$name.nc" 2>&1); then
    failures=$((failures + 1))
    echo "FAIL $name"
    sed 's/^/  /' <<<"$out"
  fi
done
echo "programs_check: $count programs, $failures failed"
((count > 0 && failures == 0))
