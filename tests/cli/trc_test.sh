#!/usr/bin/env bash
# trc_test.sh NCSIM FIXTURES: tool radius compensation end to end (docs/trc.md): `check` names
# a compensation that cannot be built at its file:line:col with the manual's id or ncsim's;
# `trace` and `time` see the compensated path.
set -uo pipefail
ncsim=$1
fixtures=$2
root=$(cd "$fixtures/../.." && pwd)
machine=$root/machines/portal_3x_tools

# expect, summary: tests/cli/expect.sh.
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"

printf '%%slot\nG00 X0 Y-10\nG41 D1\nG01 X0 Y0 F1000\nX10\nY2\nX0\nG40 X0 Y10\nM30\n' >"$work/slot.nc"
expect "check: a slot narrower than the tool is a contour violation at its block" 1 \
  '' 'slot\.nc:6:1: error: contour violation.*\[NC4701\]' -- \
  check --machine "$machine" "$work/slot.nc"
printf '%%arc\nG00 X0 Y-10\nG41 D2\nG01 X0 Y0 F1000\nX10\nG03 X14 Y4 I0 J4\nG40 G01 X20 Y4\nM30\n' >"$work/arc.nc"
expect "check: a tool radius above the inner arc radius is 90017 at the arc" 1 \
  '' 'arc\.nc:6:1: error: tool radius 5 greater or equal.*\[90017\]' -- \
  check --machine "$machine" "$work/arc.nc"
printf '%%d9\nG41 D9\nG01 X10 F100\nM30\n' >"$work/d9.nc"
expect "check: a D that is not in the tool list is NC4706 at the D word" 1 \
  '' 'd9\.nc:2:5: error: D9: tool 9 is not in the tool list.*\[NC4706\]' -- \
  check --machine "$machine" "$work/d9.nc"
printf '%%sq\nG00 X-20 Y-20\nG26 G42 D1\nG01 X0 Y0 F1000\nX100\nY100\nX0\nY0\nG40 X-20 Y-20\nM30\n' >"$work/sq.nc"
expect "trace: the square grown by 3 mm, the corner circle a G03 of radius 3 about (100, 0)" 0 \
  '^6: G03 X=103\.0000 Y=0\.0000 Z=0\.0000 F=16\.6667 centre X=100\.0000 Y=0\.0000 R=3\.0000 frame=MCS start X=100\.0000 Y=-3\.0000' '' -- \
  trace --machine "$machine" "$work/sq.nc"
expect "check: the bundled example trc_plate" 0 'trc_plate\.nc: ok' '' -- \
  check "$root/programs/trc_plate/trc_plate.nc"

summary trc_test
