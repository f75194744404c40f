#!/usr/bin/env bash
# robust_motion_test.sh NCSIM: issue 34's critical motion defects end to end (items 1-7, 11, 12,
# 19, 22): every run ends (each ncsim call is bounded by `timeout`, so a hang fails instead of
# hanging ctest), with a positioned error where the program or scenario cannot be run, the
# same verdict from `check` as from `time` / `run`, and no NaN in any output.
set -uo pipefail
bin=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"
# A hang is a failure (status 124), never a stuck test.
ncsim=$work/ncsim
printf '#!/usr/bin/env bash\nexec timeout 120 %q "$@"\n' "$bin" >"$ncsim"
chmod +x "$ncsim"
machine=$root/machines/portal_3x

# program NAME TEXT: writes $work/NAME.nc.
program() { printf '%s' "$2" >"$work/$1.nc"; }

# --- item 1, 19: the longest time is one day (core::kLongestTime); longer is an error at its line
program dwell17 $'%dwell17\nN10 G01 X10 F6000\nN20 G04 100000000000000000\nN30 M30\n'
expect "G04 1e17 s is refused by check at its line (20752), not a 0 s dwell" 1 '' \
  'dwell17\.nc:3:[0-9]+: error: dwell 1e\+17 s is longer than ncsim.s longest time, 86400 s \(one day\) \[20752\]' -- \
  check --machine "$machine" "$work/dwell17.nc"
expect "time refuses G04 1e17 s at its line (20752), after the block before it ran" 1 \
  'dwell17\.nc: stopped after 0\.1[0-9]* s' 'dwell17\.nc:3:[0-9]+: error: .*\[20752\]' -- \
  time --machine "$machine" "$work/dwell17.nc"
program dwell16 $'%dwell16\nN10 G04 10000000000000000\nN20 M30\n'
expect "G04 1e16 s: time ends at once with 20752, not after days" 1 '' 'dwell16\.nc:2:.*\[20752\]' -- \
  time --machine "$machine" "$work/dwell16.nc"
program g93 $'%g93\nN10 G93 G01 X10 F1000000000\nN20 M30\n'
expect "a G93 block time of 1e9 s is NC4032 at its line, in check" 1 '' 'g93\.nc:2:[0-9]+: error: G93 block time 1000000000 s .*\[NC4032\]' -- \
  check --machine "$machine" "$work/g93.nc"
expect "a G93 block time of 1e9 s is NC4032 at its line, in time" 1 '' 'g93\.nc:2:.*\[NC4032\]' -- \
  time --machine "$machine" "$work/g93.nc"
program indp $'%indp\nN10 X[INDP_SYN G1 G90 POS10 TIME100000000]\nN20 M30\n'
expect "an INDP TIME of 1e8 s is NC4032 at its line" 1 '' 'indp\.nc:2:.*\[NC4032\]' -- \
  time --machine "$machine" "$work/indp.nc"
program day $'%day\nN10 G04 86400\nN20 M30\n'
expect "a dwell of exactly one day is accepted" 0 'ok' '' -- check --machine "$machine" "$work/day.nc"
printf '[[event]]\nat = 0.1\nfeed_hold = true\nduration = 1e9\n' >"$work/hold.toml"
program line $'%line\nN10 G01 X100 F6000\nN20 M30\n'
expect "a scenario feed hold of 1e9 s is NC7004 at its key" 2 '' \
  'hold\.toml:4:[0-9]+: error: event\[1\]\.duration = 1000000000 s is out of range 0 \.\. 86400 s \[NC7004\]' -- \
  time --machine "$machine" --scenario "$work/hold.toml" "$work/line.nc"

# --- item 2: a loop whose only motion is a zero-length move cannot end: NC4901, in check and time
program zero $'%zero\nN10 G90 G00 X10 Y10 Z0\nN20 $WHILE 1\nN30 G01 X10 F6000\nN50 $ENDWHILE\nN60 M30\n'
expect "check: a loop of zero-length moves cannot end (NC4901 at the loop)" 1 '' \
  'zero\.nc:3:1: error: endless loop without motion.*\[NC4901\]' -- check --machine "$machine" "$work/zero.nc"
expect "time: the move before the loop runs, then NC4901 at the loop, exit 1" 1 \
  'zero\.nc: stopped after 0\.[0-9]+ s' 'zero\.nc:3:1: error: endless loop without motion.*\[NC4901\]' -- \
  time --machine "$machine" "$work/zero.nc"
expect "run -o -: the move before the loop is written, ending at X10 Y10" 1 '^[0-9.]+,2,10,10,0(,|$)' '' -- \
  run --machine "$machine" -o - "$work/zero.nc"
printf '[stop]\ntime = 5\n' >"$work/stop5.toml"
expect "a scenario [stop] time = 5 does not hide it: the run ends with NC4901" 1 '' '\[NC4901\]' -- \
  time --machine "$machine" --scenario "$work/stop5.toml" "$work/zero.nc"

# --- items 3, 4, 11, 28: arcs of a huge radius: NC4203 above 1e9 mm, exact below, no NaN
program r300 "%r300
N10 G00 X10 Y10
N20 G02 X20 Y10 I5 J-1$(printf '0%.0s' $(seq 300)) F1000
N30 M30
"
expect "check: an arc of radius 1e300 is NC4203 at its line" 1 '' 'r300\.nc:3:[0-9]+: error: circle radius 1e\+300 mm .*\[NC4203\]' -- \
  check --machine "$machine" "$work/r300.nc"
expect "time --json: an arc of radius 1e300 is an error in valid JSON, no nan" 1 \
  '^\{"program":.*"status":"error".*\}$' '' -- time --json --machine "$machine" "$work/r300.nc"
holds "time --json writes no nan or inf" bash -c "! grep -Eqi 'nan|inf' '$work/out'"
program r10 $'%r10\nN10 G00 X10 Y10\nN20 G02 X20 Y10 I5 J-10000000000 F1000\nN30 M30\n'
expect "R 1e10 on a 10 mm chord is NC4203, not a full circle to the soft limit" 1 '' 'r10\.nc:3:.*\[NC4203\]' -- \
  time --machine "$machine" "$work/r10.nc"
program r9 $'%r9\nN10 G00 X10 Y10\nN20 G02 X20 Y10 I5 J-999999999 F1000\nN30 M30\n'
expect "R 1e9 on a 10 mm chord runs as its 10 mm arc (path: 14.14 mm rapid + 10 mm), not a circle" 0 \
  'r9\.nc: [0-9.]+ s .*path 24\.142[0-9]* mm' '' -- time --audit --machine "$machine" "$work/r9.nc"
again "R 1e9: the audit is clean (no contour rounding step flagged)" 0 '^audit: ok$' ''
program r8 $'%r8\nN10 G00 X10 Y10\nN20 G02 X20 Y10 I5 J-100000000 F1000\nN30 M30\n'
expect "R 1e8: the audit's contour check is clean" 0 '^audit: ok$' '' -- \
  time --audit --machine "$machine" "$work/r8.nc"

# --- item 5: #SPLINE ON without #SPLINE OFF: M30 closes the section, the last points run
program spl $'%spl\nN10 G01 X0 Y0 F1000\nN20 #SPLINE ON\nN30 X10 Y10\nN40 X20 Y20\nN50 X30 Y10\nN60 X40 Y20\nN70 M30\n'
expect "a spline open at M30 runs to its last point, X40 Y20" 0 '' '' -- \
  run --machine "$machine" -o "$work/spl.csv" "$work/spl.nc"
holds "the last row of the spline run is at X40 Y20" \
  bash -c "grep -v '^#' '$work/spl.csv' | tail -1 | awk -F, '{ exit !(\$3 == 40 && \$4 == 20) }'"

# --- item 12: a B-spline folding back on itself: the planner keeps the axes' limits
program fold $'%fold\nN10 G01 X10 Y10 F1000\nN20 #SPLINE TYPE BSPLINE\nN30 #SPLINE ON\nN40 X20 Y20\nN50 X790 Y590\nN60 X20 Y20.001\nN70 X790 Y590.001\nN80 X20 Y20\nN90 #SPLINE OFF\nN100 M30\n'
expect "a B-spline that folds back on itself is planned within the axes' limits (audit ok)" 0 \
  '^audit: ok$' '' -- time --audit --machine "$machine" "$work/fold.nc"

# --- item 7: an override between 0 and 0.1 % is refused at its key
printf '[[event]]\nat = 0.1\noverride = 1e-300\n' >"$work/creep.toml"
expect "a scenario override of 1e-300 %% is NC7004 at its key" 2 '' \
  'creep\.toml:3:[0-9]+: error: event\[1\]\.override = 1e-300 % is out of range: 0 \(a stop\) or 0\.1 \.\. 1000 % \[NC7004\]' -- \
  time --machine "$machine" --scenario "$work/creep.toml" "$work/line.nc"

# --- item 6: sweep --tolerance below 0.001 mm/s is refused before any run
expect "sweep --tolerance 1e-300 is NC9121, exit 2" 2 '' \
  'sweep: --tolerance 1e-300 mm/s must be a number >= 0\.001 mm/s \[NC9121\]' -- \
  sweep "$root/programs/conveyor_squares/conveyor_squares.nc" --belt-velocity 50:200 --tolerance 1e-300

# --- item 22: one rule for a target beyond the soft limits: check's NC4601, refused before moving
program far $'%far\nN10 G01 X100 F6000\nN20 G00 X10000000\nN30 M30\n'
expect "check: G00 X10000000 is NC4601 at its line" 1 '' 'far\.nc:3:1: error: target X=10000000 is outside the software limits .*\[NC4601\]' -- \
  check --machine "$machine" "$work/far.nc"
expect "time: G00 X10000000 is NC4601 at its line before it moves (not NC5502 after 48 s)" 1 \
  'far\.nc: stopped after 1\.[0-9]+ s' 'far\.nc:3:1: error: target X=10000000 is outside the software limits .*\[NC4601\]' -- \
  time --machine "$machine" "$work/far.nc"

summary robust_motion_test
