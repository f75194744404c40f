#!/usr/bin/env bash
# sync_error_test.sh NCSIM: an error while synchronised (seed 004 §2.3; docs/conveyor.md
# "Errors while synchronised"): the run ends with the original error (id, line, time), the CSV
# holds the motion after it, marked by a closing comment naming the error and the stop.
set -uo pipefail
ncsim=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"
prog=$root/programs/error_while_synchronised/error_while_synchronised.nc

expect "run: NC9052 at N70 with its time, exit 1, and the note of the motion after it" 1 '' \
  'error_while_synchronised\.nc:14:1: error: run-time error at t=10\.895 s: X 3000\.29 mm beyond .*\[NC9052\]' \
  -- run -o "$work/e.csv" "$prog"
checks=$((checks + 1))
if grep -q 'synchronisation kept after NC9052 .*followed the belt for 3\.294 s; axis X braked before its soft limit 4000 mm (P-AXIS-00178)' "$work/err"; then
  echo "ok   run: stderr says what the machine did after the error"
else
  failures=$((failures + 1)); echo "FAIL run: no note on stderr"; cat "$work/err"
fi
# The CSV: rows after the error's time up to the stop, X never above 4000 mm, the last row
# at rest, then the error, the note and the stop.
checks=$((checks + 1))
verdict=$(grep -v '^#' "$work/e.csv" | awk -F, 'NR > 1 {
    if ($1 + 0 > 10.895) after++; if ($3 + 0 > xmax) xmax = $3 + 0; t = $1; x = $3
  } END { printf "%d %.6f %s %.6f", after, xmax, t, x }')
read -r after xmax t_last x_last <<<"$verdict"
if ((after > 3000)) && awk -v m="$xmax" 'BEGIN { exit !(m <= 4000 && m > 3999) }' &&
  [[ $t_last == 14.266 ]]; then
  echo "ok   run: the CSV holds $after cycles after the error, X stops at $x_last mm (<= 4000)"
else
  failures=$((failures + 1)); echo "FAIL run: after=$after xmax=$xmax t_last=$t_last"
fi
checks=$((checks + 1))
if tail -3 "$work/e.csv" | head -1 | grep -q '^# error: .*\[NC9052\]' &&
  tail -2 "$work/e.csv" | head -1 | grep -q '^# after the error: synchronisation kept after NC9052 .*it stood at t=14\.266 s' &&
  tail -1 "$work/e.csv" | grep -q '^# stop: error'; then
  echo "ok   run: the CSV ends with the error, what followed it, and the stop"
else
  failures=$((failures + 1)); echo "FAIL run: closing comments"; tail -3 "$work/e.csv"
fi
expect "time: the run stops after the motion that follows the error" 1 \
  'stopped after 14\.266 s' '\[NC9052\]' -- time "$prog"
# 50653 exactly at the limit (belt-split): a 330 mm/s belt under CONV_VEL 18000 mm/min runs
# through (its velocity from position differences rounded over 330 and stopped it at t 0.505 s).
expect "time: a belt at exactly 1.10 x CONV_VEL passes 50653 (004 l.514)" 0 \
  '1 complete of 1' '' -- time "$root/programs/synchro_lag_comoving/synchro_lag_comoving.nc" \
  --scenario "$root/tests/cli/scenario_belt_limit.toml"

# P-ERR-44009 (seed 004 §6.3.1): the error is positioned at the MC_TouchProbe that retriggers
# (line 9 of the second pass), not at the block after it, and its time is the cycle's, printed
# to the microsecond.
expect "time: P-ERR-44009 at the retriggering MC_TouchProbe, its time to the us" 1 '' \
  'probe_retriggered\.nc:9:1: error: run-time error at t=10\.33[78] s: MC_TouchProbe retriggered .*\[P-ERR-44009\]' \
  -- time "$root/programs/probe_retriggered/probe_retriggered.nc"

# NC6210 (seed 004 l.454, l.609: the joint dynamics are not ensured under #TRAFO ON): a belt
# the program cannot foresee, an encoder belt stepping 300 <-> 328 mm/s every 50 ms without
# filters, under pick_and_place_50's picks. The drives get joint setpoints whose acceleration
# (their finite differences, as the audit measures) is far above max(A+, A-): the channel warns
# at the first such cycle, the run goes on, the audit lists every overrun and exits 3.
mkdir -p "$work/delta_enc"
cp "$root"/machines/delta_picker/*.lis "$work/delta_enc/"
cp "$root/machines/delta_picker_belt/channel.lis" "$work/delta_enc/"
sed -i -e 's/^kenngr.messachse .*/&\nkenngr.achs_mode 0x00100001/' \
  -e 's/^conv_sync.enable_filter .*/conv_sync.enable_filter 0/' "$work/delta_enc/s1.lis"
grep -v MC_MoveVelocity "$root/programs/pick_and_place_50/pick_and_place_50.nc" >"$work/steps.nc"
{
  printf 'description = "an encoder belt stepping 300 <-> 328 mm/s every 50 ms"\n'
  printf '[conveyor]\nmode = "encoder"\nvelocity = 300\nprofile = [\n'
  awk 'BEGIN { for (k = 0; k < 40; ++k) printf "  { at = %.2f, velocity = %d },\n", 0.3 + 0.05 * k, k % 2 ? 300 : 328 }'
  printf ']\n[conveyor.sensor]\nkind = "light_barrier"\n'
  printf '[conveyor.workpieces]\nfirst = 100\npitch = 400\ncount = 2\nlength = 200\n'
  printf '[stop]\nline = 34\npasses = 1\n'
} >"$work/steps.toml"
expect "time: NC6210 when a belt step drives a joint's acceleration beyond max(A+, A-); the run goes on" 0 '' \
  'steps\.nc:[0-9]+:1: warning: at t=[0-9.]+ s: joint [XYZ]: \|a\| [0-9.e+]+ above its 20000 \(P-AXIS-00008\) in (the catch-up|synchronised motion|the departure) under #TRAFO ON.*\[NC6210\]' \
  -- time --machine "$work/delta_enc" --scenario "$work/steps.toml" "$work/steps.nc"
expect "time --audit: the same run lists the overruns and exits 3" 3 'audit: [0-9]+ violations' '\[NC6210\]' \
  -- time --audit --machine "$work/delta_enc" --scenario "$work/steps.toml" "$work/steps.nc"

summary sync_error
