#!/usr/bin/env bash
# move200_test.sh NCSIM: issue 12's seeded 200-move program (programs/move200, machine
# portal_3x_slow: V 100 mm/s, A 1000 mm/s^2, J 1e5 mm/s^3, C0 1, T 1 ms) in the six variants of
# docs/benchmarks.md "The 200-move table": tolerance balls 0.01 mm (G261, the program as
# bundled), VELOJUMP corners (G260), exact stops (G09 on every block), each under TRAPEZ and STEP.
# Each `ncsim time --audit` must be clean, no slower than the table, and never faster than the
# time-optimal path parameterisation without a jerk limit of bench/move200_bound (a bound no
# planner that keeps the axis limits can beat; STEP is acceleration-limited, so it must respect
# the bound too, and TRAPEZ adds the jerk limit on top).
set -uo pipefail
ncsim=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"
program=$root/programs/move200/move200.nc
machine=$root/machines/portal_3x_slow

# variant slope table_s bound_s: the table's time and the TOPP bound (docs/benchmarks.md).
check_variant() {
  local corners=$1 slope=$2 table=$3 bound=$4
  local f=$work/${corners}_$slope.nc
  sed "s/TYPE=TRAPEZ/TYPE=$slope/" "$program" >"$f"
  case $corners in
    velojump) sed -i 's/^N5 G261$/N5 G260/' "$f" ;;
    stop) sed -i 's/^N5 G261$/N5 G260/; s/^\(N[0-9][0-9][0-9]* \)\(G0[123] \)/\1G09 \2/' "$f" ;;
  esac
  "$ncsim" time --audit --machine "$machine" "$f" >"$work/out" 2>"$work/err"
  local status=$?
  local t
  t=$(sed -nE 's/^[^:]*: ([0-9.]+) s \(.*/\1/p' "$work/out")
  checks=$((checks + 1))
  if [[ $status -eq 0 && -n $t ]] && grep -q '^audit: ok$' "$work/out" &&
    awk -v t="$t" -v hi="$table" -v lo="$bound" 'BEGIN { exit !(t <= hi && t >= lo) }'; then
    echo "ok   move200 $corners $slope: $t s, audit ok, within [$bound, $table] s"
  else
    failures=$((failures + 1))
    echo "FAIL move200 $corners $slope: exit $status, $t s (want $bound..$table s, audit ok)"
    cat "$work/out" "$work/err"
  fi
}

checks=$((checks + 1))
if [[ $(grep -c '^N[0-9]* G0[123] ' "$program") -eq 200 ]] && grep -q '^N5 G261$' "$program" &&
  grep -q '^N3 #SLOPE \[TYPE=TRAPEZ\]$' "$program"; then
  echo "ok   move200: 200 moves, G261 and TRAPEZ where the variants change them"
else
  failures=$((failures + 1))
  echo "FAIL move200: the program no longer has the lines the variants edit"
fi
# (The ideal-blend bound does not credit the 0.02 mm a blend cuts off each corner, < 0.1 s in
# all: the balls' lower limit is the bound less 0.1 s.)
check_variant ball TRAPEZ 178.653 172.361
check_variant ball STEP 174.300 172.361
check_variant velojump TRAPEZ 175.629 173.335
check_variant velojump STEP 173.943 173.335
check_variant stop TRAPEZ 176.355 173.916
check_variant stop STEP 174.568 173.916

summary move200_test
