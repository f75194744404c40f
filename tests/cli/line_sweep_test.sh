#!/usr/bin/env bash
# line_sweep_test.sh NCSIM: `ncsim line sweep` end to end (docs/lines.md "ncsim line sweep"):
# two lines whose answer is known by construction (a probe armed late: the workpiece is missed
# above 150 mm/s; the laser of laser_sorter with its CONV_VEL kept: 50653 above 1.1 x 100 mm/s,
# the answer of `ncsim sweep` on the same program), the binding constraint named (a missed
# workpiece, a channel's error id, an audit violation), the same output on one thread and on
# two, and the usage errors.
set -uo pipefail
ncsim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$here/expect.sh"
late=$here/line_late/line.toml
sorter=$root/programs/lines/laser_sorter/line.toml

# line_late (tests/cli/line_late/late.nc): the probe is armed at t = 2 s (+ the cycle the
# #SYNC IN takes it), the workpiece passed the sensor after 100 mm of travel, the program lets
# it go beyond 200 mm: clean up to 300 mm / 2 s = 150 mm/s, missed above.
expect "line sweep: the late probe's limit, 300 mm / 2.001 s = 149.93 mm/s, to 0.1 mm/s" 0 \
  '^line sweep: highest belt velocity 149\.[89][0-9]* mm/s \([0-9.]+ m/min\), 149\.9[0-9]* mm/s fails \(tolerance 0\.1 mm/s\)$' '' \
  -- line sweep "$late" --belt-velocity 50:400 --tolerance 0.1 --jobs 2
cp "$work/out" "$work/late2"
holds "line sweep: the result lies within a cycle of 150 mm/s (300/2.001 .. 300/2.000)" bash -c "
  v=\$(sed -nE 's/^line sweep: highest belt velocity ([0-9.]+) mm\/s.*/\1/p' '$work/late2')
  awk -v v=\"\$v\" 'BEGIN { exit !(v >= 300 / 2.001 - 0.1 && v <= 150) }'"
again "line sweep: the binding constraint is the missed workpiece" 0 \
  '^line sweep: binding constraint at 149\.9[0-9]* mm/s: 1 workpiece missed \(the first: workpiece 1, past the belt.s end at [0-9.]+ s\)$' ''
again "line sweep: each candidate's verdict, the ones that pass with the line's figures" 0 \
  '^round 0: 50 mm/s \(3 m/min\): ok, 1 of 1 workpieces taken, [0-9.]+ per minute; end [0-9.]+ s, channel 1 \(late\) [0-9.]+ %$' ''
again "line sweep: HI fails with the missed workpiece" 0 '^round 0: 400 mm/s \(24 m/min\): fails: 1 workpiece missed' ''
expect "line sweep on one thread: the same output, byte for byte" 0 '' '' \
  -- line sweep "$late" --belt-velocity 50:400 --tolerance 0.1 --jobs 1
same "line sweep: --jobs 1 and --jobs 2 print the same" "$work/late2" "$work/out"
expect "line sweep: a range in which even LO misses it: exit 1, the reason" 1 \
  '^line sweep: no belt velocity in 200 \.\. 400 mm/s runs the line clean; at 200 mm/s: 1 workpiece missed' '' \
  -- line sweep "$late" --belt-velocity 200:400
expect "line sweep: a range that passes to HI" 0 \
  '^line sweep: highest belt velocity 120 mm/s \(7\.2 m/min\) = HI: the limit is above the range$' '' \
  -- line sweep "$late" --belt-velocity 60:120
again "line sweep: nothing binds in such a range" 0 '^line sweep: no constraint binds up to 120 mm/s$' ''

# laser_sorter with the programs' CONV_VEL (6000 mm/min = 100 mm/s): the laser's 50653 at
# 1.1 x CONV_VEL binds (seed 004 l.514), the same numbers as `ncsim sweep` of its program alone.
expect "line sweep --conv-vel keep: laser_sorter's limit is its laser's 1.1 x CONV_VEL" 0 \
  '^line sweep: highest belt velocity 109\.766 mm/s \(6\.58594 m/min\), 110\.352 mm/s fails \(tolerance 2 mm/s\)$' '' \
  -- line sweep "$sorter" --belt-velocity 50:200 --tolerance 2 --conv-vel keep
again "line sweep: the binding constraint names the channel and its error id" 0 \
  '^line sweep: binding constraint at 110\.352 mm/s: channel 1 \(laser\) \[50653\]: .*laser\.nc:10:1: error: run-time error' ''
again "line sweep: the result's figures: every part taken, both channels' utilisation" 0 \
  '^line sweep: at 109\.766 mm/s: 3 of 3 workpieces taken, [0-9.]+ per minute; end [0-9.]+ s, channel 1 \(laser\) [0-9.]+ %, channel 2 \(sorter\) [0-9.]+ %$' ''
expect "sweep of the laser's program alone finds the same limit" 0 \
  '^sweep: highest belt velocity 109\.766 mm/s \(6\.58594 m/min\), 110\.352 mm/s fails' '' \
  -- sweep "$root/programs/conveyor_squares/conveyor_squares.nc" --belt-velocity 50:200 \
  --tolerance 2 --conv-vel keep

# The audit as the constraint: line_late on a belt that fluctuates by 2 % at 20 Hz; X, which
# follows the belt while synchronised, gets the belt's jerk on top of its own path's (the audit
# counts the belt's own excesses too, docs/conveyor.md "The belt's own dynamics").
expect "line sweep: an audit violation fails a candidate, named with its axis and limit" 1 \
  '^line sweep: no belt velocity in 20 \.\. 140 mm/s runs the line clean; at 20 mm/s: channel 1 \(late\) audit: t=[0-9.]+ s line 13 axis X jerk [0-9.]+ > 200000\.8[0-9]* \([0-9]+ violations\)$' '' \
  -- line sweep "$here/line_late/fluctuating.toml" --belt-velocity 20:140 --tolerance 5

# Usage errors (exit 2, before any run).
expect "line sweep without --belt-velocity: NC9120" 2 '' 'line sweep needs --belt-velocity LO:HI \[NC9120\]' \
  -- line sweep "$late"
expect "line sweep: --belt-velocity not LO:HI: NC9120" 2 '' \
  "line sweep: --belt-velocity '200:50' must be LO:HI in mm/s with 0 <= LO < HI \[NC9120\]" \
  -- line sweep "$late" --belt-velocity 200:50
expect "line sweep: --tolerance 0: NC9121" 2 '' '\[NC9121\]' \
  -- line sweep "$late" --belt-velocity 50:200 --tolerance 0
cat >"$work/a.nc" <<'NC'
%a
G01 X10 F6000
M30
NC
cat >"$work/nobelt.toml" <<'TOML'
[[channel]]
number = 1
program = "a.nc"
machine = "portal_3x"
TOML
expect "line sweep on a line without a belt: NC9122" 2 '' 'line sweep: the line has no belt.*\[NC9122\]' \
  -- line sweep "$work/nobelt.toml" --belt-velocity 50:200
expect "--belt-velocity on line time is refused" 2 '' 'an option of line sweep' \
  -- line time "$late" --belt-velocity 50:200
summary "line sweep"
