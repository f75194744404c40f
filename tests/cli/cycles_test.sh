#!/usr/bin/env bash
# tests/cli/cycles_test.sh NCSIM: issue 33 end to end: implicit cycle calls with their files found
# by --cycles / the machine's cycles/ / the program folder, --missing-cycles skip, M values with
# an additional value in the run CSV, zero offsets from a machine's zero list.
set -uo pipefail
ncsim=$1
source "$(dirname "$0")/expect.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)

# A program with the dispenser's G800 and G805, and a G806 the machine does not configure.
cat >"$work/job.nc" <<'NC'
%job
G54
G00 X0 Y0 Z1
M200=1200
G800 [0.1, 1.0]
G805 [1, 2,, 4]
G00 X5
M30
NC
sed 's/^G805 .*/G806 [1, 2,, 4]/' "$work/job.nc" >"$work/other.nc"
expect "an unconfigured G806 is 20131 at its line, naming the parameter" 1 '' \
  'other.nc:6:1: error: unknown G function G806.*g800_prog_file\[6\] \(P-CHAN-00187\).*\[20131\]' -- \
  check --machine "$root/machines/dispenser_3x" "$work/other.nc"
cat >"$work/purge.nc" <<'NC'
%purge
G01 Z[@P4] F300
M17
NC
# a channel list that names purge.nc for G805 only in a copy of the machine
cp -r "$root/machines/dispenser_3x" "$work/machine"
sed -i 's/^g800_prog_file\[5\].*/g800_prog_file[5] purge_here.nc/' "$work/machine/channel.lis"
expect "a configured cycle file that is nowhere is NC4301 naming where ncsim looked" 1 '' \
  'purge_here.nc is not in .*cycles.*\[NC4301\]' -- check --machine "$work/machine" "$work/job.nc"
mkdir -p "$work/builder"
cp "$work/purge.nc" "$work/builder/purge_here.nc"
expect "--cycles DIR finds it" 0 'job.nc: ok' '' -- \
  check --machine "$work/machine" --cycles "$work/builder" "$work/job.nc"
expect "--missing-cycles skip checks the rest with warning NC4307" 0 'other.nc: ok, 1 warning' \
  'G806 skipped \(--missing-cycles skip\).*\[NC4307\]' -- \
  check --machine "$root/machines/dispenser_3x" --missing-cycles skip "$work/other.nc"
expect "time with --missing-cycles skip runs and names the skipped call" 0 'other.nc: [0-9.]+ s' \
  'warning: G806 skipped.*\[NC4307\]' -- \
  time --machine "$root/machines/dispenser_3x" --missing-cycles skip "$work/other.nc"
expect "--missing-cycles takes error or skip only" 2 '' 'missing-cycles' -- \
  check --missing-cycles maybe "$work/job.nc"
expect "run with the copy and --cycles completes" 0 '' '' -- \
  run --machine "$work/machine" --cycles "$work/builder" -o "$work/job.csv" "$work/job.nc"
checks=$((checks + 1))
last=$(grep -v '^#' "$work/job.csv" | tail -n 1)
if grep -q '^# tech .* M200=1200$' "$work/job.csv" && [[ $(cut -d, -f3 <<<"$last") == 105 ]]; then
  echo "ok   the CSV has '# tech ... M200=1200' and ends at G54's X 100 + 5"
else
  failures=$((failures + 1))
  echo "FAIL the CSV's tech line or end position"
  grep '^# tech' "$work/job.csv" | head -3
  echo "$last"
fi
# The zero-offset list (P-ZERO) and the feed unit (P-CHAN-00108) as the loader reads them.
cp -r "$root/machines/mill_3x" "$work/zero"
printf 'np_grp[1].achse[3].versch 10000\n' >>"$work/zero/zero.lis"
expect "a zero offset of an axis the channel does not have is NC3016 at its key" 2 '' \
  'zero\.lis:[0-9]+:[0-9]+: error: np_grp\[1\]\.achse\[3\]\.versch.*\[NC3016\]' -- \
  check --machine "$work/zero" "$work/job.nc"
cp -r "$root/machines/mill_3x" "$work/feed"
printf 'prog_start.feedrate_factor 0\n' >>"$work/feed/channel.lis"
printf '%%f\nG01 X10 F1000\nM30\n' >"$work/feed.nc"
expect "P-CHAN-00108 = 0 is warning NC3022, F stays mm/min" 0 'feed\.nc: ok' '\[NC3022\]' -- \
  check --machine "$work/feed" "$work/feed.nc"

# --max-time ends a program that runs endlessly, with the reason (issue 33 item 9).
cat >"$work/endless.nc" <<'NC'
%endless
$WHILE 1
  G01 X10 F6000
  G01 X0
$ENDWHILE
M30
NC
expect "check calls it endless" 0 'runs endlessly' '' -- check "$work/endless.nc"
expect "time --max-time 2 stops at 2 s and says why" 0 'stop: stop\.time \(--max-time\) at 2 s' '' -- \
  time --max-time 2 "$work/endless.nc"
expect "run --max-time 1 closes its CSV with the reason" 0 '' 'run stopped \(--max-time\)' -- \
  run --max-time 1 -o "$work/endless.csv" "$work/endless.nc"
expect "--max-time takes a positive number of seconds" 2 '' 'max-time' -- \
  time --max-time 0 "$work/endless.nc"
# Without --max-time or [stop] it does not run until killed: it ends after whole passes, when
# the decoder finds it back in the same state, and says so (docs/interp.md "Endless programs").
expect "time without --max-time ends an endless program and says why" 0 \
  'stop: endless \(from line [34], NC4904\)' 'runs endlessly from line [34]' -- time "$work/endless.nc"
expect "run without --max-time closes its CSV with the reason" 0 '' 'runs endlessly from line [34]' -- \
  run -o "$work/endless2.csv" "$work/endless.nc"
checks=$((checks + 1))
if grep -q '^# stop: endless$' "$work/endless2.csv"; then
  echo "ok   the CSV of an endless run ends with '# stop: endless'"
else
  failures=$((failures + 1))
  echo "FAIL the CSV of an endless run: $(tail -n 2 "$work/endless2.csv")"
fi
# Technology functions (docs/interp.md "Technology functions"): mill_3x's M06 MVS_SVS 5.5 s,
# M03 MVS_SNS 1.2 s, M05 MNS_SNS 0.9 s in their own column, and a scenario's [tech] over them.
cat >"$work/tool.nc" <<'NC'
%tool
G00 X10 Y10 Z50
T2 M06
S6000 M03
G01 X60 F3000
G00 Z80 M05
M30
NC
expect "time counts the acknowledgement waits in their own tech column" 0 \
  'tool.nc: .* dwell 0 s, tech 7\.6 s, exact stop' '' -- \
  time --machine "$root/machines/mill_3x" "$work/tool.nc"
expect "time --blocks puts the tool change's 5.5 s on its block, under tech_s" 0 \
  '^3 5\.5 0 0 0 0 0 0 5\.5 ' '' -- \
  time --blocks --machine "$root/machines/mill_3x" "$work/tool.nc"
printf '[tech]\nM6 = 2\nM3 = 0\n' >"$work/tech.toml"
expect "a scenario's [tech] replaces the machine's times (M06 2 s, M03 0 s: 2.9 s)" 0 \
  'tech 2\.9 s' '' -- \
  time --scenario "$work/tech.toml" --machine "$root/machines/mill_3x" "$work/tool.nc"
expect "time --json has the tech split" 0 '"tech":7\.6' '' -- \
  time --json --machine "$root/machines/mill_3x" "$work/tool.nc"
printf '[tech]\nM6 = -2\n' >"$work/bad_tech.toml"
expect "a negative [tech] time is NC7004 at its line" 2 '' 'bad_tech.toml:2:.*\[NC7004\]' -- \
  time --scenario "$work/bad_tech.toml" --machine "$root/machines/mill_3x" "$work/tool.nc"
expect "run writes the waiting cycles: as many rows as time has cycles" 0 '' '' -- \
  run -o "$work/tool.csv" --machine "$root/machines/mill_3x" "$work/tool.nc"
rows=$(grep -vc '^#' "$work/tool.csv")
cycles=$("$ncsim" time --machine "$root/machines/mill_3x" "$work/tool.nc" | grep -o '([0-9]* cycles' | tr -dc 0-9)
checks=$((checks + 1))
if [[ $rows -eq $((cycles + 1)) ]]; then
  echo "ok   run's rows (header included) are time's cycles + 1 with the tech waits"
else
  failures=$((failures + 1))
  echo "FAIL run rows $rows, time cycles $cycles"
fi

summary cycles_test
