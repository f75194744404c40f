#!/usr/bin/env bash
# cli_test.sh NCSIM FIXTURES: end-to-end checks of exit statuses and output of `ncsim`.
set -uo pipefail
ncsim=$1
fixtures=$2

# expect, same: tests/cli/expect.sh.
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"

expect "a clean program checks with status 0" 0 'clean\.nc: ok' '' -- check "$fixtures/clean.nc"
expect "every error is reported, status 1" 1 '' 'two_errors\.nc: 2 errors' -- \
  check "$fixtures/two_errors.nc"
expect "an error names file:line:col and the manual id" 1 '' \
  'two_errors\.nc:3:1: error: .*\[20218\]' -- check "$fixtures/two_errors.nc"
expect "a syntax error is located at the offending column" 1 '' \
  'two_errors\.nc:4:[0-9]+: error: ' -- check "$fixtures/two_errors.nc"
"$ncsim" check "$fixtures/two_errors.nc" 2>"$work/caret" >/dev/null
checks=$((checks + 1))
if grep -qx '\$ENDIF' "$work/caret" && grep -qx '\^' "$work/caret"; then
  echo "ok   the source line and a caret follow the message"
else
  failures=$((failures + 1)); echo "FAIL the source line and a caret follow the message"
  cat "$work/caret"
fi
expect "a missing program file is a usage error" 2 '' 'no such file' -- check "$work/nope.nc"
expect "a directory is not a program" 2 '' 'not a regular file' -- check "$fixtures"
expect "no subcommand is a usage error" 2 '' '' --
expect "an unknown option is a usage error" 2 '' '' -- check --frobnicate "$fixtures/clean.nc"
expect "check needs a program" 2 '' '' -- check
expect "trace needs a program" 2 '' '' -- trace
expect "golden needs check or bless" 2 '' '' -- golden
root=$(cd "$fixtures/../.." && pwd)
expect "a file that is no TOML is a bad scenario, status 2" 2 '' 'clean\.nc:[0-9]+:[0-9]+: error: TOML syntax.*\[NC7001\]' -- \
  check "$fixtures/clean.nc" --scenario "$fixtures/clean.nc"
expect "the scenario's V.E. values are the decode-only state" 0 'X=7\.5000' '' -- \
  trace "$fixtures/external.nc" --scenario "$fixtures/scenario_ve.toml"
expect "--ve wins over the scenario's value" 0 'X=12\.5000' '' -- \
  trace "$fixtures/external.nc" --scenario "$fixtures/scenario_ve.toml" --ve OFFSET=12.5
expect "every error of a bad scenario, with file:line, status 2" 2 '' \
  'scenario_bad\.toml:3:[0-9]+: error: ve\.OFFSET must be a number, not a string \[NC7003\]' -- \
  check "$fixtures/external.nc" --scenario "$fixtures/scenario_bad.toml"
expect "the second error of a bad scenario is reported too" 2 '' \
  'scenario_bad\.toml:6:[0-9]+: error: event\[1\]\.override = 150000 % is out of range.*\[NC7004\]' -- \
  check "$fixtures/external.nc" --scenario "$fixtures/scenario_bad.toml"
expect "a missing scenario file is a usage error" 2 '' 'no such scenario file' -- \
  check "$fixtures/clean.nc" --scenario "$work/nope.toml"
expect "a line the program does not have is NC7012" 2 '' \
  'scenario_line\.toml:2:[0-9]+: error: event\[1\]\.line = 99 is beyond the last line.*\[NC7012\]' -- \
  check "$fixtures/external.nc" --scenario "$fixtures/scenario_line.toml"
expect "time with a scenario's V.E. values runs" 0 'external\.nc: [0-9.e-]+ s' '' -- \
  time "$fixtures/external.nc" --scenario "$fixtures/scenario_ve.toml"
expect "time plays a scenario with an override event" 0 'external\.nc: [0-9.e-]+ s' '' -- \
  time "$fixtures/external.nc" --scenario "$fixtures/scenario_events.toml"
printf '[[event]]\nat = 0.1\naxis_override = { X = 150 }\n' >"$work/axis_override.toml"
expect "run refuses an INDP axis override above 100 % with its position, status 2" 2 '' \
  'axis_override\.toml:3:19: error: event\[1\]\.axis_override\.X = 150 % is above 100 %.*\[NC6105\]' -- \
  run "$fixtures/external.nc" --scenario "$work/axis_override.toml"
printf '[[event]]\nat = 0.1\noverride = 150\n' >"$work/override_150.toml"
expect "an override above 100 % under type REDUCED is refused at its value, status 2" 2 '' \
  'override_150\.toml:3:12: error: event\[1\]\.override = 150 % is above 100 %.*NCSIM-CHAN-630.*\[NC6102\]' -- \
  time "$fixtures/external.nc" --scenario "$work/override_150.toml"
holds "NC6102 shows the scenario's line and a caret under the value (issue 34 item 24)" \
  bash -c "grep -qx 'override = 150' '$work/err' && grep -qx '           ^' '$work/err'"
expect "check refuses the override time would refuse (NC6102), status 2" 2 '' 'override_150\.toml:3:12: .*\[NC6102\]' -- \
  check "$fixtures/external.nc" --scenario "$work/override_150.toml"
printf '[ve]\nSEL = 0\n[[event]]\nat = 0.2\nfeed_hold = true\nduration = 0.5\n' >"$work/hold.toml"
expect "a 0.5 s feed hold makes the run (1.507 s) 0.5 s longer" 0 've_branch\.nc: 2\.007 s' '' -- \
  time "$fixtures/ve_branch.nc" --scenario "$work/hold.toml"
# time --blocks under a scenario: the held time and the time lost to override and holds, per
# block and in the total (docs/ipo.md "Time lost"). The 0.5 s hold falls in line 2 (X10 at
# 10 mm/s takes 1 s): line 2 stands for the hold less its ramp down and loses 0.5 s (the
# ramps down and up too).
checks=$((checks + 1))
"$ncsim" time --blocks "$fixtures/ve_branch.nc" --scenario "$work/hold.toml" >"$work/hb" 2>&1
"$ncsim" time --blocks --json "$fixtures/ve_branch.nc" --scenario "$work/hold.toml" >"$work/hj" 2>&1
held2=$(awk '$1 == 2 { print $12 }' "$work/hb")
lost2=$(awk '$1 == 2 { print $13 }' "$work/hb")
held_sum=$(awk '!/^#/ && NF == 14 { s += $12 } END { print s }' "$work/hb")
lost_sum=$(awk '!/^#/ && NF == 14 { s += $13 } END { printf "%.9f", s }' "$work/hb")
lost_total=$(sed -E 's/.*"total_s":[^,]+,"distance_mm":[^,]+,"lost_s":([^,]+),.*/\1/' "$work/hj")
if grep -q '^# line .* waiting_s held_s lost_s feed_cap_mm_min$' "$work/hb" &&
  [[ $held_sum == "$held2" ]] &&
  awk -v h="$held2" -v l="$lost2" 'BEGIN { exit !(h > 0.4 && h <= 0.5 && l >= 0.5 && l < 0.6) }' &&
  awk -v a="$lost_sum" -v b="$lost_total" 'BEGIN { d = a - b; exit !(d < 1e-9 && d > -1e-9) }' &&
  grep -q "\"held\":$held2}" "$work/hj" &&
  grep -Eq 'held 0\.4[0-9]* s; lost to override and holds 0\.5[0-9]* s$' \
    <("$ncsim" time "$fixtures/ve_branch.nc" --scenario "$work/hold.toml"); then
  echo "ok   time --blocks under a scenario: held and lost per block and in the total"
else
  failures=$((failures + 1))
  echo "FAIL time --blocks held / lost: held $held2 (sum $held_sum), lost $lost2 (sum $lost_sum, total $lost_total)"
  cat "$work/hb" "$work/hj"
fi
printf '[ve]\nOFFSET = 7.5\n[[event]]\nat = 0.1\noverride = 50\n' >"$work/half.toml"
expect "an override of 50 % from 0.1 s loses time, none held" 0 \
  'held 0 s; lost to override and holds 0\.[0-9]+ s$' '' -- \
  time "$fixtures/external.nc" --scenario "$work/half.toml"
expect "without a scenario time prints no lost time" 0 'held 0 s$' '' -- \
  time "$fixtures/long_line.nc"
# The channel plays V.E. writes and [stop] (docs/scenario.md "Wiring into the channel loop").
expect "a V.E. write at 0.5 s reaches the \$IF after the move: the Y20 branch (line 4) runs" 0 \
  '^[0-9.e-]+,4,10,20,0$' '' -- \
  run "$fixtures/ve_branch.nc" --scenario "$fixtures/scenario_ve_write.toml" -o -
printf '[ve]\nSEL = 0\n[stop]\ncycles = 100000\n' >"$work/no_write.toml"
expect "without the write the \$ELSE branch (line 6) runs" 0 '^[0-9.e-]+,6,10,5,0$' '' -- \
  run "$fixtures/ve_branch.nc" --scenario "$work/no_write.toml" -o -
expect "time reports a [stop] time with its reason, status 0" 0 \
  '^stop: stop\.time .* at 0\.25 s$' '' -- \
  time "$fixtures/ve_branch.nc" --scenario "$fixtures/scenario_stop.toml"
expect "time --json names the stop" 0 '"stop":"stop\.time"' '' -- \
  time "$fixtures/ve_branch.nc" --scenario "$fixtures/scenario_stop.toml" --json
expect "run closes the CSV with the stop reason" 0 '^# stop: stop\.time$' \
  'run stopped \(scenario .*stop\.time at t=0\.25 s' -- \
  run "$fixtures/ve_branch.nc" --scenario "$fixtures/scenario_stop.toml" -o -
printf '[ve]\nSEL = 0\n[[event]]\nat = 0.2\nfeed_hold = true\n' >"$work/hold_forever.toml"
expect "a hold nothing releases ends the run with NC6301 instead of hanging, status 1" 1 \
  '"stop":"error"' 'run-time error at t=0\.[0-9]+ s: the path stands by feed hold.*\[NC6301\]' -- \
  time --json "$fixtures/ve_branch.nc" --scenario "$work/hold_forever.toml"
# The stop reason, always (docs/scenario.md "[stop]"): time --json "stop", the CSV's last line.
expect "time --json names the program end" 0 '"stop":"program end"\}$' '' -- \
  time --json "$fixtures/long_line.nc"
expect "time --json names an error as the stop" 1 '"status":"error".*"stop":"error"\}$' '' -- \
  time --json --machine "$root/machines/static_saw" "$fixtures/sync_in.nc"
expect "run closes the CSV with # stop: program end" 0 '^# stop: program end$' '' -- \
  run "$fixtures/long_line.nc" --every 1000 -o -
printf '[stop]\ncycles = 10\n' >"$work/stop_cycles.toml"
expect "time --json names stop.cycles" 0 '"cycles":10,.*"stop":"stop\.cycles"' '' -- \
  time --json "$fixtures/long_line.nc" --scenario "$work/stop_cycles.toml"
printf '[ve]\nSEL = 0\n[stop]\nline = 2\npasses = 1\n' >"$work/stop_passes.toml"
expect "run closes the CSV with # stop: stop.passes" 0 '^# stop: stop\.passes$' '' -- \
  run "$fixtures/ve_branch.nc" --scenario "$work/stop_passes.toml" -o -
for sc in "$fixtures/scenario_ve_write.toml" "$work/hold.toml"; do
  checks=$((checks + 1))
  "$ncsim" run "$fixtures/ve_branch.nc" --scenario "$sc" -o "$work/w1.csv" 2>/dev/null
  "$ncsim" run "$fixtures/ve_branch.nc" --scenario "$sc" -o "$work/w2.csv" 2>/dev/null
  total=$("$ncsim" time "$fixtures/ve_branch.nc" --scenario "$sc" --json |
    sed -E 's/.*"total_s":([^,]+).*/\1/')
  if cmp -s "$work/w1.csv" "$work/w2.csv" && [[ $total == "$(grep -v "^#" "$work/w1.csv" | tail -1 | cut -d, -f1)" ]]
  then
    echo "ok   under $(basename "$sc") time equals run's last t, and reruns are byte-identical"
  else
    failures=$((failures + 1))
    echo "FAIL $(basename "$sc"): time $total, run $(grep -v "^#" "$work/w1.csv" | tail -1 | cut -d, -f1)"
  fi
done
mkdir -p "$work/sprog"
cp "$fixtures/external.nc" "$work/sprog/"
printf '[ve]\nOFFSET = 3.25\n' >"$work/sprog/scenario.toml"
expect "the program folder's scenario.toml is used by default" 0 'X=3\.2500' '' -- \
  trace "$work/sprog/external.nc"
expect "--scenario overrides the program folder's scenario.toml" 0 'X=7\.5000' '' -- \
  trace "$work/sprog/external.nc" --scenario "$fixtures/scenario_ve.toml"
printf '[ve]\nOFFSET = 3.25\n[conveyor]\nmode = "encoder"\nvelocity = 300\n' >"$work/sprog/scenario.toml"
expect "a conveyor table in the default scenario is read with the rest of it" 0 'X=3\.2500' '' -- \
  trace "$work/sprog/external.nc"
expect "the bundled part_variants program checks with its scenario" 0 'part_variants\.nc: ok' '' -- \
  check "$root/programs/part_variants/part_variants.nc"
expect "a bundled machine can be named with --machine" 0 'clean\.nc: ok' '' -- \
  check --machine "$root/machines/laser_portal" "$fixtures/clean.nc"
expect "a missing machine folder is a configuration error" 2 '' 'could not be loaded' -- \
  check --machine "$work/no_machine" "$fixtures/clean.nc"
mkdir -p "$work/prog"
cp "$fixtures/clean.nc" "$work/prog/"
echo "delta_picker" >"$work/prog/machine"
expect "the program folder's machine file names the machine" 0 'clean\.nc: ok' '' -- \
  check "$work/prog/clean.nc"
echo "no_such_machine" >"$work/prog/machine"
expect "an unknown machine named by the program folder is a configuration error" 2 '' \
  'could not be loaded' -- check "$work/prog/clean.nc"
expect "a semantic error fails the check with the manual's id" 1 '' \
  'no_feed\.nc:3:[0-9]+: error: .*\[20008\]' -- check "$fixtures/no_feed.nc"
expect "trace prints one command per line, ending with END" 0 '^7: END M30$' '' -- \
  trace "$fixtures/clean.nc"
expect "trace of a program with syntax errors reports them, status 1" 1 '' '\[20218\]' -- \
  trace "$fixtures/two_errors.nc"
expect "trace records the error that ended the stream" 1 '^# 20008 line 3$' '\[20008\]' -- \
  trace "$fixtures/no_feed.nc"
expect "V.E. values come from --ve" 0 'X=12\.5000' '' -- \
  trace "$fixtures/external.nc" --ve OFFSET=12.5
expect "a --ve without a number is a usage error" 2 '' 'is not a number' -- \
  trace "$fixtures/external.nc" --ve OFFSET=abc
expect "a --ve without = is a usage error" 2 '' 'NAME=value' -- \
  check "$fixtures/external.nc" --ve OFFSET
"$ncsim" trace --max-commands 3 "$root/programs/pick_and_place/pick_and_place.nc" \
  >"$work/endless" 2>/dev/null
status=$?
checks=$((checks + 1))
# Three commands, then the marker line (issue 9 defect 7); status 0: the program is fine.
if [[ $status -eq 0 && $(wc -l <"$work/endless") -eq 4 ]] &&
  [[ $(tail -1 "$work/endless") == "# truncated after 3 commands (--max-commands)" ]]; then
  echo "ok   --max-commands cuts an endless program and says so"
else
  failures=$((failures + 1)); echo "FAIL --max-commands cuts an endless program"
  cat "$work/endless"
fi
expect "--syntax-only skips the semantic check" 0 'no_feed\.nc: ok \(syntax\)' '' -- \
  check --syntax-only "$fixtures/no_feed.nc"
expect "--syntax-only still reports syntax errors" 1 '' '\[20218\]' -- \
  check --syntax-only "$fixtures/two_errors.nc"
expect "--syntax-only takes no machine" 2 '' 'takes no --machine' -- \
  check --syntax-only --machine "$root/machines/portal_3x" "$fixtures/clean.nc"
expect "warnings keep status 0 and are counted in the verdict" 0 'no_end\.nc: ok, 1 warning' \
  'no_end\.nc:3:1: warning: .*\[NC2019\]' -- check "$fixtures/no_end.nc"
expect "help exits 0" 0 'check' '' -- --help
expect "an unknown command is named" 2 '' "unknown command 'chek'" -- chek "$fixtures/clean.nc"
expect "a negative --max-commands is a usage error" 2 '' 'max-commands' -- \
  trace --max-commands -1 "$fixtures/clean.nc"
expect "a --ve name given twice is a usage error" 2 '' 'OFFSET is given more than once' -- \
  trace "$fixtures/external.nc" --ve OFFSET=1 --ve OFFSET=2
checks=$((checks + 1))
if "$ncsim" check - <"$fixtures/clean.nc" 2>"$work/err" | grep -q '^<stdin>: ok$'; then
  echo "ok   - reads the program from standard input"
else
  failures=$((failures + 1)); echo "FAIL - reads the program from standard input"
  cat "$work/err"
fi
if [[ -w /dev/full ]]; then
  checks=$((checks + 1))
  "$ncsim" trace "$fixtures/clean.nc" >/dev/full 2>"$work/err"
  got=$?
  if [[ $got -ne 0 ]] && grep -q 'cannot write' "$work/err"; then
    echo "ok   a write error fails the command with a message"
  else
    failures=$((failures + 1)); echo "FAIL a write error fails the command (exit $got)"
    cat "$work/err"
  fi
  checks=$((checks + 1))
  "$ncsim" check "$fixtures/clean.nc" >/dev/full 2>"$work/err"
  got=$?
  if [[ $got -eq 2 ]]; then
    echo "ok   check's verdict that cannot be written fails"
  else
    failures=$((failures + 1)); echo "FAIL check's verdict that cannot be written (exit $got)"
  fi
fi
mkdir -p "$work/sub"
printf '%%main\nG00 X0\nL bad_sub.nc\nM30\n' >"$work/sub/main.nc"
printf '%%bad_sub\nP1 = 1\n$IF P1 == 2\nG01 X[[1]\n$ENDIF\nM17\n' >"$work/sub/bad_sub.nc"
expect "check reports the syntax errors of a called subroutine file" 1 '' \
  'bad_sub\.nc:4:[0-9]+: error: .*\[NC1' -- check "$work/sub/main.nc"
expect "check names a called subroutine file with syntax errors" 1 '' '\[NC4306\]' -- \
  check "$work/sub/main.nc"
printf '%%e\nP1 = 0\n$WHILE 1\nG01 X[P1] F600\nP1 = 1 - P1\n$ENDWHILE\nM30\n' >"$work/endless.nc"
expect "an endless program is named in the verdict" 0 'ok \(runs endlessly from line [0-9]+\)' \
  '' -- check "$work/endless.nc"
printf '%%e\nP1 = 0\n$WHILE 1\nP1 = 1 - P1\n$ENDWHILE\nM30\n' >"$work/stuck.nc"
expect "an endless loop without motion is an error" 1 '' 'stuck\.nc:3:1: error: .*cannot end.*\[NC4901\]' \
  -- check "$work/stuck.nc"

# time / run on the path interpolator (issue 12). long_line.nc: 700 mm at 100 mm/s with
# A = 3000 mm/s^2 (STEP, jerk A / T): 7 + 1/30 + 0.001 s, rounded up to the 1 ms cycle:
# 7035 cycles.
expect "time of a long line at F is length / F + F / A + T, to the cycle" 0 \
  'long_line\.nc: 7\.035 s \(7035 cycles of 1 ms\)' '' -- time "$fixtures/long_line.nc"
# The total for people to the microsecond: 56306 cycles of 1 ms summed read 56.306000000000004
# (51132 cycles since issue 36's kept G261 corners, docs/planner.md "Tolerance balls").
expect "time prints its total to the microsecond, not the sum's rounding" 0 \
  'laser_repaired\.nc: 51\.132 s \(51132 cycles of 1 ms\)' '' -- \
  time "$root/programs/laser_repaired/laser_repaired.nc"
expect "time --blocks gives the line's time, distance and feeds" 0 \
  '^4 7\.035 700 6000 6000 0 7\.035 0 0 0 0 0 0 -$' '' -- time --blocks "$fixtures/long_line.nc"
# F above what the axes allow is capped, with the cap in the last column (issue 12; portal_3x:
# X v_max P-AXIS-00212 500 mm/s = 30000 mm/min, F 60000 asks twice that).
printf '%%cap\nN10 G01 X500 F60000\nN20 X0 F6000\nM30\n' >"$work/cap.nc"
expect "time --blocks names the axes' cap of an F above their velocity" 0 \
  '^2 [0-9.]+ [0-9.]+ 60000 30000 0 [0-9.]+ 0 0 0 0 0 0 30000$' '' -- time --blocks "$work/cap.nc"
expect "time --blocks leaves the cap column empty where F is reachable" 0 \
  '^3 [0-9.]+ [0-9.]+ 6000 6000 0 [0-9.]+ 0 0 0 0 0 0 -$' '' -- time --blocks "$work/cap.nc"
expect "time --json gives the cap of a capped block" 0 \
  '"line":2,"time_s":[0-9.]+,"distance_mm":[0-9.]+,"feed_programmed_mm_min":60000,"feed_reached_mm_min":30000,"feed_cap_mm_min":30000,' \
  '' -- time --json --blocks "$work/cap.nc"
expect "time --json" 0 '"total_s":7\.035' '' -- time --json --blocks "$fixtures/long_line.nc"
# The documented steps listed apart per kind, with the one closest to its formula (issue 12):
# corner_angles' 45 / 90 / 135 degree corners and a reversal at VELOJUMP, C0 1, A 3000, T 1 ms.
expect "time --audit lists the documented steps per kind" 0 \
  '^audit: VELOJUMP steps 14, closest to C0 min\(A\+, \|A-\|\) T: t=[0-9.]+ s line [0-9]+ axis [XY] \|dv\| 3 of 3 mm/s at the link velocity [0-9.]+ mm/s$' \
  '' -- time --audit "$root/programs/corner_angles/corner_angles.nc"
expect "time --audit-steps lists every documented step, each against its formula" 0 \
  '^audit: step VELOJUMP t=[0-9.]+ s line [0-9]+ axis [XY] \|dv\| [0-9.e-]+ of 3 mm/s at the link velocity [0-9.]+ mm/s$' \
  '' -- time --audit-steps "$root/programs/corner_angles/corner_angles.nc"
expect "run --audit-steps: the steps with the verdict on stderr" 0 '' \
  '^audit: step VELOJUMP t=' -- run --audit-steps -o "$work/steps.csv" "$root/programs/corner_angles/corner_angles.nc"
expect "time --audit passes on the long line" 0 '^audit: ok$' '' -- \
  time --audit "$fixtures/long_line.nc"
expect "run --audit passes on the long line" 0 '' '^audit: ok$' -- \
  run --audit -o "$work/audit.csv" "$fixtures/long_line.nc"
expect "a run-time error at its line (FEED_CONT on a static unit), status 1" 1 '' \
  'sync_in\.nc:4:1: error: run-time error at t=0 s: #SYNC IN FEED_CONT.*FEED_CONT_AUTO.*x_virtual.*\[NC9060\]' -- \
  time --machine "$root/machines/static_saw" "$fixtures/sync_in.nc"
expect "run stops at a run-time error, status 1" 1 '' '#SYNC IN FEED_CONT.*\[NC9060\]' -- \
  run --machine "$root/machines/static_saw" -o "$work/sync.csv" "$fixtures/sync_in.nc"
checks=$((checks + 1))
if [[ -f $work/sync.csv ]] && no_temp "$work/sync.csv" &&
  [[ $(tail -2 "$work/sync.csv" | head -1) == "# error: "*"#SYNC IN FEED_CONT"*"NC9060"* ]] &&
  [[ $(tail -1 "$work/sync.csv") == "# stop: error" ]]; then
  echo "ok   run keeps the trajectory up to the error, with a closing comment"
else
  failures=$((failures + 1)); echo "FAIL run keeps the trajectory up to the error"
  tail -3 "$work/sync.csv"
fi
expect "the measured workpiece's V.E. values reach the program after #SYNC IN" 0 \
  ',8,[-0-9.e]+,107,0$' '' -- \
  run --machine "$root/machines/laser_portal" -o - "$fixtures/conveyor_ve/conveyor_ve.nc"
expect "run --detail adds the conveyor display variables on a conveyor machine" 0 \
  '^t,line,X,Y,Z,.*,Z\.ferr,current_pos_master,current_v_master,current_a_master,pos_master_comp,v_master_comp,a_master_comp,synchro_lag$' '' -- \
  run --detail --machine "$root/machines/laser_portal" -o - "$fixtures/conveyor_ve/conveyor_ve.nc"
expect "time --audit names a rotary axis's units in degrees" 0 \
  '^audit: C \|v\| [0-9.]+ / 1080 deg/s, \|a\| [0-9.]+ / 20000 deg/s\^2' '' -- \
  time --audit "$root/programs/rotary_table/rotary_table.nc"
expect "time --audit says the jerk is not limited under an acceleration-limited slope (never |j| 0)" 0 \
  '^audit: X .*\|j\| not limited \(acceleration-limited slope\)$' '' -- \
  time --audit "$root/programs/rotary_table/rotary_table.nc"
# Issue 36 item 4: a run that ends in a run-time error is audited to its last cycle; exit 1.
expect "time --audit after a run-time error: the audit of every cycle run, the error's exit 1" 1 \
  '^audit: 25 violations$' '\[50653\]' -- time --audit "$root/programs/belt_too_fast/belt_too_fast.nc"
expect "run --audit after a run-time error: the audit on stderr after the error" 1 '' \
  '^audit: 25 of the violations are the belt.s own' -- \
  run --audit -o "$work/error_audit.csv" "$root/programs/belt_too_fast/belt_too_fast.nc"
expect "time --audit of conveyor tracking checks the axes on their setpoints (belt offset, catch-up): ok" 0 \
  '^audit: ok$' '' -- time --audit "$root/programs/conveyor_squares/conveyor_squares.nc"
# A program that ends right after #SYNC OUT (conveyor_squares' first sheet, then M30): X still
# moves with the belt at the end; the run says so (NC6106; issue 34 item 18: it was silent).
mkdir -p "$work/moving"
cp "$root/programs/conveyor_squares/machine" "$root/programs/conveyor_squares/scenario.toml" "$work/moving/"
sed -n '1,15p' "$root/programs/conveyor_squares/conveyor_squares.nc" | grep -v '^\$FOR' >"$work/moving/moving.nc"
echo M30 >>"$work/moving/moving.nc"
for cmd in time run; do
  expect "$cmd: a run that ends with an axis still moving warns (NC6106), naming it" 0 '' \
    '^ncsim: warning: the run ended at t=[0-9.]+ s with axes still moving: X at 100 mm/s .*\[NC6106\]$' -- \
    $cmd "$work/moving/moving.nc"
done
expect "a run that ends with the axes standing does not warn" 0 '' '' -- time "$fixtures/long_line.nc"
holds "no NC6106 for a run that ends standing" bash -c "! grep -q NC6106 '$work/err'"
expect "time --audit: full feed in +X and -X on a fast belt keeps X within v_max (PCS1 velocity split)" 0 \
  '^audit: ok$' '' -- \
  time --audit --machine "$root/machines/laser_portal" "$fixtures/conveyor_split/conveyor_split.nc"
expect "run to a full device is a write error, status 2" 2 '' 'cannot write' -- \
  run -o /dev/full "$fixtures/long_line.nc"
expect "run --every 0 is a usage error" 2 '' '' -- run --every 0 "$fixtures/long_line.nc"
"$ncsim" run -o "$work/a.csv" "$fixtures/long_line.nc" 2>/dev/null
"$ncsim" run -o "$work/b.csv" "$fixtures/long_line.nc" 2>/dev/null
"$ncsim" run -o - "$fixtures/long_line.nc" >"$work/c.csv" 2>/dev/null
checks=$((checks + 1))
rows=$(grep -cv '^#' "$work/a.csv")
last_t=$(grep -v "^#" "$work/a.csv" | tail -1 | cut -d, -f1)
if [[ $rows -eq 7036 && $last_t == "7.035" ]] && cmp -s "$work/a.csv" "$work/b.csv" &&
  cmp -s "$work/a.csv" "$work/c.csv" && [[ $(sed -n 6p "$work/a.csv") == "t,line,X,Y,Z" ]]; then
  echo "ok   run: one row per cycle (header + time / T), last t equals time, byte-identical reruns"
else
  failures=$((failures + 1)); echo "FAIL run rows / last t / reruns: rows $rows last t $last_t"
  head -8 "$work/a.csv"
fi
# A program with arcs, a dwell and a blend: time's total equals run's last t to the cycle.
isg="$root/programs/isg_reference_example/isg_reference_example.nc"
total=$("$ncsim" time "$isg" 2>/dev/null | sed -E 's/^.*: ([0-9.e+-]+) s \(.*$/\1/')
"$ncsim" run -o "$work/isg.csv" "$isg" 2>/dev/null
checks=$((checks + 1))
if [[ -n $total && $(grep -v "^#" "$work/isg.csv" | tail -1 | cut -d, -f1) == "$total" ]]; then
  echo "ok   time equals the last t of run on isg_reference_example ($total s)"
else
  failures=$((failures + 1)); echo "FAIL time ($total) vs run: $(grep -v "^#" "$work/isg.csv" | tail -1)"
fi
"$ncsim" run --every 10 --detail -o "$work/d.csv" "$fixtures/long_line.nc" 2>/dev/null
checks=$((checks + 1))
if [[ $(grep -cv '^#' "$work/d.csv") -eq 705 ]] &&
  [[ $(sed -n 6p "$work/d.csv") == "t,line,X,Y,Z,X.v,X.a,Y.v,Y.a,Z.v,Z.a,v_path,feed,X.ferr,Y.ferr,Z.ferr" ]]; then
  echo "ok   run --every 10 --detail: every 10th cycle and the last one, detail columns"
else
  failures=$((failures + 1)); echo "FAIL run --every 10 --detail"
  head -8 "$work/d.csv"
fi

# The channel loop (issue 12): run-time errors stop the channel at file:line:col with the time
# and the id, exit 1; the CSV keeps the trajectory up to the stop and names the error.
expect "a soft limit reached at run time stops the channel: position, time, id" 1 \
  'soft_limit\.nc: stopped after 8\.522 s' \
  'soft_limit\.nc:7:1: error: run-time error at t=8\.523 s: axis X: command position .* above the maximum soft position limit 800 mm \(P-AXIS-00178\) \[NC5502\]' -- \
  time "$fixtures/soft_limit.nc"
status=0
"$ncsim" run -o "$work/soft.csv" "$fixtures/soft_limit.nc" 2>/dev/null || status=$?
checks=$((checks + 1))
if [[ $status -eq 1 && -f $work/soft.csv ]] &&
  [[ $(tail -2 "$work/soft.csv" | head -1) == "# error: "*"soft_limit.nc:7:1: error: run-time error at t=8.523 s"*"[NC5502]" ]] &&
  [[ $(tail -1 "$work/soft.csv") == "# stop: error" ]] &&
  [[ $(tail -3 "$work/soft.csv" | head -1 | cut -d, -f1) == "8.522" ]] &&
  no_temp "$work/soft.csv"; then
  echo "ok   run stopped by a run-time error: rows up to the stop, closing # error comment"
else
  failures=$((failures + 1)); echo "FAIL run stopped by a run-time error"
  tail -3 "$work/soft.csv"
fi
# --- planner: an error in a block of a subroutine file names that file and its line
# (docs/ipo.md "Blocks of subroutine files"); `time --blocks` names such blocks file:line. The
# target beyond the soft limit is refused before it moves, as `check` reports it (NC4601, issue
# 34 item 22); it was run-time error NC5502 on the way.
sub_prog="$fixtures/../../programs/subroutine_soft_limit/subroutine_soft_limit.nc"
expect "a soft limit reached in a subroutine file names the subroutine file and its line" 1 '' \
  'part_contour\.sub:10:1: error: target X=805 is outside the software limits .*\(P-AXIS-00177/00178\) \[NC4601\]' -- \
  time "$sub_prog"
checks=$((checks + 1))
if grep -q '^N70 G03' "$work/err" && ! grep -q 'subroutine_soft_limit\.nc:10:' "$work/err"; then
  echo "ok   the subroutine file's block is echoed, the main program is not named"
else
  failures=$((failures + 1)); echo "FAIL the subroutine file's block is echoed"
  cat "$work/err"
fi
expect "time --blocks names a subroutine file's blocks file:line, the main's by line" 1 \
  '^[^ ]*part_contour\.sub:4 [0-9.]+ ' '' -- time --blocks "$sub_prog"
status=0
"$ncsim" run -o "$work/sub.csv" "$sub_prog" 2>/dev/null || status=$?
checks=$((checks + 1))
if [[ $status -eq 1 ]] &&
  [[ $(tail -2 "$work/sub.csv" | head -1) == "# error: "*"part_contour.sub:10:1: error: target X=805"*"[NC4601]" ]]; then
  echo "ok   the CSV's closing comment names the subroutine file"
else
  failures=$((failures + 1)); echo "FAIL the CSV's closing comment names the subroutine file"
  tail -2 "$work/sub.csv"
fi
# G60 on actual positions: time and run agree to the cycle, exact-stop waiting included.
total=$("$ncsim" time "$fixtures/exact_stop.nc" 2>/dev/null | sed -E 's/^.*: ([0-9.e+-]+) s \(.*$/\1/')
"$ncsim" run --detail -o "$work/es.csv" "$fixtures/exact_stop.nc" 2>/dev/null
checks=$((checks + 1))
# (time prints to the microsecond, the CSV the exact double: compared as numbers.)
last_t=$(grep -v "^#" "$work/es.csv" | tail -1 | cut -d, -f1)
if [[ -n $total ]] && awk -v a="$total" -v b="$last_t" 'BEGIN { exit !(a - b < 1e-9 && b - a < 1e-9) }' &&
  "$ncsim" time --blocks "$fixtures/exact_stop.nc" | grep -Eq '^3 [0-9.]+ 100 6000 6000 0 [0-9.]+ 0 0 0\.0[0-9]+ 0 0 0 -$'; then
  echo "ok   G60 waits for the actual position (exact stop time > 0); time equals run ($total s)"
else
  failures=$((failures + 1)); echo "FAIL G60 exact stop: time $total, run $(grep -v "^#" "$work/es.csv" | tail -1 | cut -d, -f1)"
  "$ncsim" time --blocks "$fixtures/exact_stop.nc"
fi

# --- static-saw: G74 (docs/homing.md): X then Y home to P-AXIS-00152 (0) at P-AXIS-00219; the
# homing time is counted on the G74 line (waiting), and the path goes on from the reference point.
expect "time --blocks shows the G74 homing time on its line" 0 \
  '^5 1\.964 0 0 0 0 0 0 0 0 1\.964 0 0 -$' '' -- time --blocks "$fixtures/homing.nc"
expect "after G74 the next block starts at the reference point" 0 \
  '^6 0\.135 10 6000' '' -- time --blocks "$fixtures/homing.nc"
printf '%%h\n#TRAFO ON\nG74 X1\nM30\n' >"$work/g74_trafo.nc"
expect "G74 with an active coupling is 20137 at its line" 1 '' \
  'g74_trafo\.nc:3:1: error: .*\[20137\]' -- check --machine "$root/machines/delta_picker" "$work/g74_trafo.nc"

summary cli
