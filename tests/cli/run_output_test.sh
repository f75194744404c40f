#!/usr/bin/env bash
# run_output_test.sh NCSIM FIXTURES: `ncsim run` / `time` output contracts (issue 12):
# --cycle-us sets the cycle (named in the CSV head, rows N us apart, bad values exit 2 with the
# option named); `run -o FILE` writes a temporary FILE.XXXXXX.tmp and renames it when complete
# (a failing start leaves no FILE and no temporary file and does not touch an existing FILE; a run-time error leaves a
# complete FILE with a closing comment); the CSV's numbers are the setpoints' doubles (a cruise
# row against the closed form of a STEP line, the end point to the last digit).
set -uo pipefail
ncsim=$1
fixtures=$2
root=$(cd "$fixtures/../.." && pwd)

# expect, again, same, holds, summary: tests/cli/expect.sh.
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"

# ---- --cycle-us ----------------------------------------------------------------------------
# rows_apart FILE DT: the k-th data row's t is k DT (the first row is the end of the first
# cycle; to 1e-12 s), and there is more than one row.
rows_apart() {
  grep -v '^#' "$1" | tail -n +2 | awk -F, -v dt="$2" '
    { want = NR * dt; d = $1 - want; if (d > 1e-12 || d < -1e-12) { bad = 1; print "row " NR ": t=" $1 ", want " want; exit } }
    END { exit (bad || NR < 2) }'
}
# head_cycle FILE DT: the head's "# cycle: <T> s" line reads back to DT.
head_cycle() {
  grep '^# cycle: ' "$1" | awk -v dt="$2" '$1 == "#" && $2 == "cycle:" && $4 == "s" { found = ($3 + 0 == dt + 0) } END { exit !found }'
}
for us in 500 1000 2000; do
  "$ncsim" run --cycle-us "$us" -o "$work/c$us.csv" "$fixtures/long_line.nc" 2>"$work/err"
  status=$?
  dt=$(awk -v us="$us" 'BEGIN { printf "%.17g", us * 1e-6 }')
  holds "--cycle-us $us: run ends with status 0" test "$status" -eq 0
  holds "--cycle-us $us: the CSV head names the cycle ($dt s)" head_cycle "$work/c$us.csv" "$dt"
  holds "--cycle-us $us: rows are $us us apart (t = k T)" rows_apart "$work/c$us.csv" "$dt"
done
# The same line at 0.5 ms and at 2 ms: time's total (to the microsecond) is run's last t, and
# the cycles differ: 700 mm / 100 mm/s + 1/30 s + T rounded up to T.
for us in 500 2000; do
  last=$(grep -v '^#' "$work/c$us.csv" | tail -1 | cut -d, -f1)
  total=$("$ncsim" time --cycle-us "$us" "$fixtures/long_line.nc" 2>/dev/null | sed -E 's/^.*: ([0-9.e+-]+) s \(.*$/\1/')
  holds "time --cycle-us $us: the total ($total s) is run's last t ($last s)" \
    awk -v a="$total" -v b="$last" 'BEGIN { d = a - b; exit !(d < 5e-7 && d > -5e-7) }'
done
holds "the cycle changes the time: 0.5 ms and 2 ms give different totals" \
  test "$(grep -v '^#' "$work/c500.csv" | tail -1 | cut -d, -f1)" != \
  "$(grep -v '^#' "$work/c2000.csv" | tail -1 | cut -d, -f1)"
expect "time --cycle-us 500 names the cycle in its total" 0 'cycles of 0\.5 ms\)' '' -- \
  time --cycle-us 500 "$fixtures/long_line.nc"
# Bad values: the option, the value and why (cli/cycle_option.hpp), status 2, for every command
# that takes it.
not_digits='is not a whole number of microseconds in digits \(1 to 1000000 us; 1000 us = 1 ms\)$'
while IFS='|' read -r bad why; do
  for cmd in run time report; do
    expect "$cmd --cycle-us '$bad': '$why', status 2" 2 '' "^--cycle-us: $why" -- \
      "$cmd" --cycle-us "$bad" "$fixtures/long_line.nc" -o "$work/never.csv"
  done
done <<LIST
0|0 us is below the smallest cycle, 1 us$
-5|-5 us is below the smallest cycle, 1 us$
1000001|1000001 us is above the largest cycle, 1000000 us \(1 s\)$
1e12|'1e12' $not_digits
abc|'abc' $not_digits
1.5|'1\.5' $not_digits
|needs a value
LIST
# The documented maximum is a cycle the program may not take: the position controller needs
# Kv x cycle <= 1, so it is refused naming the option, the axis and its longest cycle (issue 34).
expect "--cycle-us 1000000 on portal_3x: refused naming the option, the axis's Kv and its limit" 2 '' \
  "^ncsim: error: --cycle-us 1000000: axis X's Kv P-AXIS-00099 getriebe\[0\]\.kv = [0-9.]+ 1/s takes a cycle of at most [0-9]+ us" -- \
  time --cycle-us 1000000 "$fixtures/long_line.nc"
expect "sweep --cycle-us 0 is refused the same way" 2 '' \
  '^--cycle-us: 0 us is below the smallest cycle, 1 us$' -- sweep --cycle-us 0 "$fixtures/long_line.nc"
holds "no bad --cycle-us run wrote a file" no_file "$work/never.csv"

# ---- NCSIM-CHAN-610 ncsim.cycle_time: the channel list's cycle, --cycle-us over it ---------
# cycle_machine NAME VALUE: portal_3x in $work/NAME with `ncsim.cycle_time VALUE`.
cycle_machine() {
  cp -r "$root/machines/portal_3x" "$work/$1"
  printf 'ncsim.cycle_time %s\n' "$2" >>"$work/$1/channel.lis"
  echo "$work/$1"
}
"$ncsim" run --machine "$(cycle_machine cy500 500)" -o "$work/cy500.csv" "$fixtures/long_line.nc" 2>/dev/null
holds "ncsim.cycle_time 500: the CSV head names 5e-04 s" head_cycle "$work/cy500.csv" 0.0005
holds "ncsim.cycle_time 500: rows 500 us apart" rows_apart "$work/cy500.csv" 0.0005
same "ncsim.cycle_time 500: the CSV is --cycle-us 500's, byte for byte" "$work/c500.csv" "$work/cy500.csv"
expect "ncsim.cycle_time 500: time counts cycles of 0.5 ms" 0 'cycles of 0\.5 ms\)' '' -- \
  time --machine "$work/cy500" "$fixtures/long_line.nc"
"$ncsim" run --machine "$work/cy500" --cycle-us 2000 -o "$work/cy500_2000.csv" "$fixtures/long_line.nc" 2>/dev/null
same "--cycle-us 2000 overrides ncsim.cycle_time 500" "$work/c2000.csv" "$work/cy500_2000.csv"
"$ncsim" run -o "$work/cy_none.csv" "$fixtures/long_line.nc" 2>/dev/null
same "no ncsim.cycle_time, no --cycle-us: 1 ms, as --cycle-us 1000" "$work/c1000.csv" "$work/cy_none.csv"
for bad in 0 1000001 1.5; do
  expect "ncsim.cycle_time $bad is refused at its line (NC3004 / NC3003), status 2" 2 '' \
    "cy_$bad/channel\.lis:3:[0-9]+: error: ncsim\.cycle_time \(NCSIM-CHAN-610\)" -- \
    run -o "$work/never.csv" --machine "$(cycle_machine "cy_$bad" "$bad")" "$fixtures/long_line.nc"
done
holds "no refused ncsim.cycle_time run wrote a file" no_file "$work/never.csv"

# ---- run -o FILE: written whole or not at all ---------------------------------------------
# no_output NAME FILE: neither FILE nor FILE.tmp exists.
no_output() {
  holds "$1: no file and no temporary file" no_file "$2"
}
out=$work/new.csv
expect "a missing program is a usage error, status 2" 2 '' 'no such file' -- \
  run -o "$out" "$work/missing.nc"
no_output "missing program" "$out"
expect "a machine folder that does not exist is a usage error, status 2" 2 '' '' -- \
  run -o "$out" --machine "$work/no_machine" "$fixtures/long_line.nc"
no_output "missing machine" "$out"
expect "a program with syntax errors stops before the run, status 1" 1 '' 'two_errors\.nc' -- \
  run -o "$out" "$fixtures/two_errors.nc"
no_output "syntax errors" "$out"
expect "a bad scenario stops before the run, status 2" 2 '' 'NC7003' -- \
  run -o "$out" --scenario "$fixtures/scenario_bad.toml" "$fixtures/external.nc"
no_output "bad scenario" "$out"
expect "an output folder that does not exist is a write error, status 2" 2 '' 'cannot write' -- \
  run -o "$work/no_dir/x.csv" "$fixtures/long_line.nc"
holds "no output folder: nothing created" test ! -e "$work/no_dir"

# An existing FILE survives every failing start untouched.
printf 'keep me\n' >"$work/keep.csv"
cp "$work/keep.csv" "$work/keep.orig"
"$ncsim" run -o "$work/keep.csv" "$work/missing.nc" >/dev/null 2>&1
"$ncsim" run -o "$work/keep.csv" "$fixtures/two_errors.nc" >/dev/null 2>&1
"$ncsim" run -o "$work/keep.csv" --cycle-us 0 "$fixtures/long_line.nc" >/dev/null 2>&1
"$ncsim" run -o "$work/keep.csv" --machine "$work/no_machine" "$fixtures/long_line.nc" >/dev/null 2>&1
same "an existing FILE is not clobbered by a failing start" "$work/keep.orig" "$work/keep.csv"
holds "a failing start leaves no FILE.tmp beside an existing FILE" no_temp "$work/keep.csv"

# A run-time error (X beyond its soft limit 800 mm at t=8.523 s, NC5502) ends the run: FILE is
# complete, replaces the old one, every row has the head's fields, and two closing comments name
# the error.
expect "a run-time error ends the run with status 1" 1 '' 'soft_limit\.nc:7:1: error: .*\[NC5502\]' -- \
  run -o "$work/keep.csv" "$fixtures/soft_limit.nc"
holds "run-time error: FILE replaced, no FILE.tmp left" \
  bash -c "test -s '$work/keep.csv' && ! compgen -G '$work/keep.csv.*tmp' >/dev/null"
complete_csv() {
  local f=$1
  [[ $(head -1 "$f") == "# ncsim run" ]] || return 1
  [[ $(tail -2 "$f" | head -1) == "# error: "*"soft_limit.nc:7:1: error: run-time error at t=8.523 s: "*"[NC5502]" ]] || return 1
  [[ $(grep -v '^#' "$f" | tail -1 | cut -d, -f1) == 8.522 ]] || return 1
  [[ $(tail -1 "$f") == "# stop: error" ]] || return 1
  grep -v '^#' "$f" | awk -F, 'NR == 1 { n = NF; next } NF != n { exit 1 } END { exit NR != 8523 }'
}
holds "run-time error: the CSV is complete, rows whole, closing comments name the error" \
  complete_csv "$work/keep.csv"

# ---- the CSV's numbers are the setpoints ------------------------------------------------
# portal_3x, X700 F6000 from X0, STEP: A = 3000 mm/s^2, planned with j = A / T (docs/planner.md),
# so the ramp up takes v/A + T and covers v (v/A + T) / 2. In the cruise, x(t) = v t - v (v/A + T)/2
# with v = 100 mm/s: x(3) = 300 - 50 (1/30 + 0.001) = 298.283333...; v = 100, a = 0.
"$ncsim" run --detail -o "$work/detail.csv" "$fixtures/long_line.nc" 2>/dev/null
holds "--detail head: t,line,X,Y,Z,X.v,X.a,..." \
  grep -q '^t,line,X,Y,Z,X\.v,X\.a,Y\.v,Y\.a,Z\.v,Z\.a,v_path,feed,X\.ferr,Y\.ferr,Z\.ferr$' "$work/detail.csv"
cruise() {
  awk -F, '$1 == "3" {
    x = 300 - 50 * (1 / 30 + 0.001); d = $3 - x
    found = 1; ok = (d < 1e-9 && d > -1e-9) && $6 + 0 == 100 && $7 + 0 == 0 && $4 == "0" && $5 == "0"
    if (!ok) print "t=3: " $0 " (want X " x ")"
  } END { exit !(found && ok) }' "$work/detail.csv"
}
holds "t=3 s: X is the closed-form cruise position to 1e-9 mm, X.v 100, X.a 0, Y and Z exactly 0" cruise
# The first cycle is the jerk phase of STEP's j = A / T = 3e6 mm/s^3: at t = T, x = j T^3 / 6 =
# 0.0005 mm, v = j T^2 / 2 = 1.5 mm/s, a = j T = 3000 mm/s^2, each the same double as the closed
# form (the CSV prints 5e-04; awk reads both texts to doubles and compares them with ==).
first_cycle() {
  grep -v '^#' "$work/detail.csv" | sed -n 2p | awk -F, '{
    ok = $1 == 0.001 && $2 == 4 && $3 == 0.0005 && $6 == 1.5 && $7 == 3000 && $12 == 1.5 && $13 == 100
    if (!ok) print "first row: " $0
  } END { exit !ok }'
}
holds "t=T: X, X.v, X.a and v_path are the closed-form jerk-phase values, exactly" first_cycle
holds "the last row holds X at the programmed end, 700, to the last digit" \
  test "$(grep -v '^#' "$work/detail.csv" | tail -1 | cut -d, -f3)" = 700
# Every number in the CSV is the shortest text of its double: printing the value read back with
# 17 significant digits and reading that again gives the same double, and no field has a
# trailing zero in its fraction or a leading '+' (what %.17g or fixed formats would give).
shortest() {
  grep -v '^#' "$1" | tail -n +2 | awk -F, '{
    for (i = 1; i <= NF; i++) {
      if ($i ~ /^\+/ || $i ~ /\.[0-9]*0$/ || $i ~ /\.($|e)/) { print "field " i " of row " NR ": " $i; exit 1 }
      if (sprintf("%.17g", $i) + 0 != $i + 0) { print "field " i " of row " NR ": " $i; exit 1 }
    }
  }'
}
holds "every CSV field is a shortest round-trip number" shortest "$work/detail.csv"

# ---- --every N: rows of every Nth cycle, and always the last cycle ------------------------
# 7035 cycles at --every 10: the rows of cycles 10, 20, ..., 7030, then the last one (t 7.035,
# X on the programmed end 700), so the last t is time's total also at --every N; after a
# run-time error the last row is the last good cycle (t 8.522), not the last multiple of N.
last_row() { grep -v '^#' "$1" | tail -1; }
"$ncsim" run --every 10 -o "$work/every.csv" "$fixtures/long_line.nc" 2>/dev/null
holds "--every 10: a row every 10 cycles, then the last cycle (704 rows)" \
  test "$(grep -v '^#' "$work/every.csv" | tail -n +2 | wc -l)" -eq 704
holds "--every 10: the last row is the program end (t 7.035, X 700)" \
  test "$(last_row "$work/every.csv")" = "7.035,4,700,0,0"
holds "--every 10: the row before it is cycle 7030" \
  test "$(grep -v '^#' "$work/every.csv" | tail -2 | head -1 | cut -d, -f1)" = 7.03
"$ncsim" run --every 1000 -o "$work/every_err.csv" "$fixtures/soft_limit.nc" 2>/dev/null
holds "--every 1000 and a run-time error: the last row is the last good cycle (t 8.522)" \
  test "$(last_row "$work/every_err.csv" | cut -d, -f1)" = 8.522
holds "--every 1000 and a run-time error: the closing comments follow it" \
  test "$(tail -1 "$work/every_err.csv")" = "# stop: error"
"$ncsim" run --every 7035 -o "$work/every_one.csv" "$fixtures/long_line.nc" 2>/dev/null
holds "--every 7035: the last cycle is written once" \
  test "$(grep -v '^#' "$work/every_one.csv" | tail -n +2 | wc -l)" -eq 1
# Bad values: the option, the value and why (cli/cycle_option.hpp every_error), status 2, no
# file (before: CLI11's "Value abc not in range 1 to 1099511627776" for every kind of mistake).
every_digits='is not a whole number of cycles in digits \(1 to 1099511627776 cycles; 1 writes every cycle\)$'
while IFS='|' read -r bad why; do
  expect "run --every '$bad': '$why', status 2" 2 '' "^--every: $why" -- \
    run --every "$bad" -o "$work/never.csv" "$fixtures/long_line.nc"
done <<LIST
abc|'abc' $every_digits
1.5|'1\.5' $every_digits
0|0 is below the smallest, 1 \(a row every cycle\)$
1099511627777|1099511627777 is above the largest, 1099511627776 \(2\^40\) cycles$
LIST
holds "no bad --every run wrote a file" no_file "$work/never.csv"

summary run_output_test
