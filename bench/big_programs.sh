#!/usr/bin/env bash
# big_programs.sh [BLOCKS...]
#
# Memory independent of program length (issue 9): `ncsim check --syntax-only`, `ncsim check`
# and `ncsim trace` of generated programs of BLOCKS blocks each (default: 10,000,000 and
# 130,000,000 = 5.1 GB), one core (taskset -c $CORE, default 1), peak RSS and CPU time from
# /usr/bin/time -v.
# Target: peak RSS < 64 MB for every program and command; STRICT=1 makes a miss exit 1.
#
# The programs are written to $NCSIM_BIG_DIR (default /tmp/ncsim-big), never into the
# repository; they are regenerated only when missing (deterministic: seed 1). The full check
# and the trace run on a copy of machines/portal_3x with +-2 m software limits (the generated
# coordinates leave the 800 x 600 mm table); the trace goes to /dev/null. Needs `time` and a
# Release build with -DNCSIM_BENCH=ON in $NCSIM_BUILD_DIR (default build/release-bench; built
# here if missing). Disk: about 40 bytes per block.
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${NCSIM_BUILD_DIR:-$REPO/build/release-bench}"
WORK="${NCSIM_BIG_DIR:-/tmp/ncsim-big}"
LIMIT_KB=$((64 * 1024))
if [[ $# -gt 0 ]]; then sizes=("$@"); else sizes=(10000000 130000000); fi

[[ -x /usr/bin/time ]] || { echo "big_programs: needs /usr/bin/time (apt-get install time)" >&2; exit 2; }
if [[ ! -x "$BUILD/cli/ncsim" || ! -x "$BUILD/bench/gen_program" ]]; then
  cmake -S "$REPO" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DNCSIM_BENCH=ON >/dev/null
  cmake --build "$BUILD" --target ncsim gen_program >&2
fi
mkdir -p "$WORK"
machine="$WORK/portal_3x_wide"
rm -rf "$machine"
cp -r "$REPO/machines/portal_3x" "$machine"
sed -i 's/^kenngr.swe_pos .*/kenngr.swe_pos 20000000/; s/^kenngr.swe_neg .*/kenngr.swe_neg -20000000/' \
  "$machine"/x.lis "$machine"/y.lis "$machine"/z.lis

failed=0
printf '| blocks | file [MB] | command | exit | CPU [s] | blocks/s | peak RSS [MB] |\n'
printf '|---|---|---|---|---|---|---|\n'
for blocks in "${sizes[@]}"; do
  prog="$WORK/bench_$blocks.nc"
  [[ -s "$prog" ]] || "$BUILD/bench/gen_program" --blocks "$blocks" --seed 1 --nc "$prog"
  mb=$(($(stat -c %s "$prog") / 1000000))
  for cmd in "check --syntax-only" "check --machine $machine" "trace --max-commands 0 --machine $machine"; do
    set +e
    /usr/bin/time -v taskset -c "${CORE:-1}" "$BUILD/cli/ncsim" $cmd "$prog" >/dev/null 2>"$WORK/time.txt"
    status=$?
    set -e
    rss=$(awk -F': ' '/Maximum resident/ {print $2}' "$WORK/time.txt")
    cpu=$(awk -F': ' '/User time|System time/ {s += $2} END {printf "%.2f", s}' "$WORK/time.txt")
    rate=$(awk -v b="$blocks" -v c="$cpu" 'BEGIN {printf "%.2f M", b / c / 1e6}')
    printf '| %s | %s | %s | %s | %s | %s | %.1f |\n' "$blocks" "$mb" "${cmd%% --machine*}" \
      "$status" "$cpu" "$rate" "$(awk -v r="$rss" 'BEGIN {print r / 1024}')"
    if [[ $status -ne 0 || $rss -gt $LIMIT_KB ]]; then failed=1; fi
  done
done
if [[ "${STRICT:-0}" == 1 && $failed -ne 0 ]]; then exit 1; fi
