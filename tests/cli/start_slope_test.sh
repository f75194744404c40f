#!/usr/bin/env bash
# start_slope_test.sh NCSIM FIXTURES: the channel's P-CHAN-00071 prog_start.slope.profile end to
# end (issue 12; isg-language.md §5.5): portal_3x's lists with the key added, `time` of the long
# line (700 mm at 100 mm/s; X: A = 3000 mm/s^2, ramps 60 ms, so J = 50000 mm/s^3).
set -uo pipefail
ncsim=$1
fixtures=$2
root=$(cd "$fixtures/../.." && pwd)

# expect, holds, summary: tests/cli/expect.sh.
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"

# machine_with VALUE: portal_3x in $work/m_VALUE with `prog_start.slope.profile VALUE` as the
# channel list's third line.
machine_with() {
  local dir=$work/m_$1
  cp -r "$root/machines/portal_3x" "$dir"
  printf 'prog_start.slope.profile %s\n' "$1" >>"$dir/channel.lis"
  [[ $(sed -n 3p "$dir/channel.lis") == "prog_start.slope.profile $1" ]] || echo "setup: line 3 of $dir/channel.lis"
  echo "$dir"
}

# 0 (STEP, also the bundled lists without the key): L / v + v / A + T = 7 + 1/30 + 0.001 s.
expect "P-CHAN-00071 0: the acceleration-limited time, as without the key" 0 \
  'long_line\.nc: 7\.035 s \(7035 cycles of 1 ms\)' '' -- \
  time --machine "$(machine_with 0)" "$fixtures/long_line.nc"
# 1 (TRAPEZ): v = 100 < A^2 / J = 180, each ramp 2 sqrt(v / J): 7 + 0.0894427 s -> 7.090 s.
expect "P-CHAN-00071 1: the jerk-limited time L/v + 2 sqrt(v/J), to the cycle" 0 \
  'long_line\.nc: 7\.09 s \(7090 cycles of 1 ms\)' '' -- \
  time --machine "$(machine_with 1)" "$fixtures/long_line.nc"
expect "P-CHAN-00071 1: the audit checks the jerk (|j| within J), not 'not limited'" 0 \
  '^audit: X \|v\| 100 / 500 mm/s, \|a\| [0-9.]+ / 3000 mm/s\^2, \|j\| [0-9.]+ / 50000 mm/s\^3$' '' -- \
  time --audit --machine "$work/m_1" "$fixtures/long_line.nc"
# #SLOPE DEFAULT after #SLOPE [TYPE=STEP] on the TRAPEZ channel: the jerk-limited time again.
printf '%%default\nN10 #SLOPE [TYPE=STEP]\nN20 #SLOPE DEFAULT\nN30 G01 X700 F6000\nN40 M30\n' \
  >"$work/default.nc"
expect "#SLOPE DEFAULT returns to the list's TRAPEZ" 0 'default\.nc: 7\.09 s \(7090 cycles' '' -- \
  time --machine "$work/m_1" "$work/default.nc"
printf '%%step\nN10 #SLOPE [TYPE=STEP]\nN30 G01 X700 F6000\nN40 M30\n' >"$work/step.nc"
expect "#SLOPE [TYPE=STEP] on the TRAPEZ channel is acceleration-limited" 0 \
  'step\.nc: 7\.035 s \(7035 cycles' '' -- time --machine "$work/m_1" "$work/step.nc"
# Refused values, at the channel list's line 3 with the key, the id and the diagnostic, exit 2.
expect "P-CHAN-00071 3 (HSC) is NC3013 at its line" 2 '' \
  'm_3/channel\.lis:3:[0-9]+: error: prog_start\.slope\.profile \(P-CHAN-00071\) = 3 \(HSC; .*write 0 \(STEP\), 1 \(TRAPEZ\) or 2 \(SIN2\) \[NC3013\]' -- \
  time --machine "$(machine_with 3)" "$fixtures/long_line.nc"
expect "P-CHAN-00071 7 is outside 0..3 (NC3004) at its line" 2 '' \
  'm_7/channel\.lis:3:[0-9]+: error: prog_start\.slope\.profile \(P-CHAN-00071\) = 7 is outside its range 0\.\.3 \[NC3004\]' -- \
  run -o "$work/never.csv" --machine "$(machine_with 7)" "$fixtures/long_line.nc"
holds "a refused list writes no CSV" no_file "$work/never.csv"

summary start_slope_test
