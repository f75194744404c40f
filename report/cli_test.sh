#!/usr/bin/env bash
# report/cli_test.sh NCSIM FIXTURES: end-to-end checks of `ncsim report` and `run --report`
# (docs/report.md): exit statuses, the page written atomically and byte-identical on reruns,
# the same page from `run --report` with the CSV unchanged, the outcome of a failed or stopped
# run on the page, the conveyor series and workspace of a conveyor run, write errors with their
# ids. The helpers `expect` and `same` are tests/cli/expect.sh's.
set -uo pipefail
ncsim=$1
fixtures=$2
programs=$fixtures/../../programs
# shellcheck source=../tests/cli/expect.sh
source "$(dirname "$0")/../tests/cli/expect.sh"

expect "report exits 0 and prints where the page is" 0 "^report: $work/a.html\$" '' -- \
  report "$fixtures/clean.nc" -o "$work/a.html"
holds "the page is written" test -s "$work/a.html"
holds "the audit table knows an acceleration-limited slope (no jerk checked), as the CLI" \
  grep -q '"j_limit":[0-9.e+]*,"jerk_cycles":0}' "$work/a.html"
holds "no temporary file is left" no_temp "$work/a.html"
holds "the page inlines uPlot" grep -q 'uPlot (v1\.6\.32)' "$work/a.html"
holds "the page says the run was ok" grep -q '"outcome":"ok"' "$work/a.html"
holds "no conveyor: no workspace, no named series" grep -q '"workspace":null' "$work/a.html"
expect "a rerun exits 0" 0 '' '' -- report "$fixtures/clean.nc" -o "$work/b.html"
same "reruns are byte-identical" "$work/a.html" "$work/b.html"

expect "run without --report" 0 '' '' -- run "$fixtures/clean.nc" -o "$work/plain.csv"
expect "run --report exits 0 and names the page on stderr" 0 '' "^report: $work/c.html\$" -- \
  run "$fixtures/clean.nc" -o "$work/with.csv" --report "$work/c.html"
same "run --report writes the page of report" "$work/a.html" "$work/c.html"
same "run --report leaves the CSV unchanged" "$work/plain.csv" "$work/with.csv"

expect "a run-time error still writes the page, exit 1, the error on stderr as run prints it" \
  1 '' 'run-time error at t=8\.523 s' -- report "$fixtures/soft_limit.nc" -o "$work/soft.html"
holds "the page shows the outcome and the error id" \
  grep -q '"outcome":"error".*NC5502' "$work/soft.html"

expect "a scenario stop writes the page, exit 0" 0 '' '' -- \
  report "$fixtures/ve_branch.nc" --scenario "$fixtures/scenario_stop.toml" -o "$work/stop.html"
holds "the page shows the stop reason" grep -q '"outcome":"stopped","stop":"[^"]' "$work/stop.html"

# A conveyor run (docs/report.md "Conveyor"): the belt series, the phases, the workspace, the
# three sheets' rows of the time per workpiece.
expect "the conveyor example's report exits 0" 0 '' '' -- \
  report "$programs/conveyor_squares/conveyor_squares.nc" -o "$work/conv.html"
for name in belt_v_actual belt_v_raw belt_v_filtered current_pos_master pos_master_comp \
  synchro_lag phase.waiting phase.catch_up phase.synchronised phase.leaving; do
  holds "the conveyor page has the series $name" grep -q "{\"name\":\"$name\"" "$work/conv.html"
done
holds "the conveyor page has the workspace and pos_limit of laser_portal" \
  grep -q '"workspace":{"lower":\[-200,-200,-100\],"upper":\[4000,2500,300\],"pos_limit":-190,' \
  "$work/conv.html"

holds "the conveyor page's axes were jerk-checked (jerk-limited slope while synchronised)" \
  grep -q '"jerk_cycles":[1-9][0-9]*}' "$work/conv.html"
holds "the conveyor page has three complete workpiece rows" \
  grep -q '"workpieces":{"summary":{"workpieces":3,"complete":3,' "$work/conv.html"
summary=$("$ncsim" time "$programs/conveyor_squares/conveyor_squares.nc" --json |
  grep -o '"workpiece_summary":{[^}]*}' | sed 's/^"workpiece_summary"://')
holds "the page's time per workpiece is time --json's, to the byte" \
  grep -qF "\"workpieces\":{\"summary\":$summary,\"rows\":[{\"index\":1," "$work/conv.html"

# Under #TRAFO ON the joints are audited apart (docs/report.md "Audit"), as the CLI lists them.
expect "the delta picker's report exits 0" 0 '' '' -- \
  report "$programs/delta_pick/delta_pick.nc" -o "$work/delta.html"
holds "the delta page lists the three moved joints under #TRAFO, jerk-checked" \
  grep -qE '"joints":\[(\{[^}]*"jerk_cycles":[1-9][0-9]*,"index":[0-2]\},?){3}\]' "$work/delta.html"
holds "a page without #TRAFO lists no joint" grep -q '"joints":\[\]' "$work/a.html"

expect "an unwritable page exits 2 with NC8100 naming the file and why" 2 '' \
  "the report: cannot write '$work/no/such/dir/x\.html': its folder '$work/no/such/dir' does not exist \[NC8100\]" -- \
  report "$fixtures/clean.nc" -o "$work/no/such/dir/x.html"
expect "an empty -o exits 2 with NC8101" 2 '' 'NC8101' -- report "$fixtures/clean.nc" -o ""
expect "a missing program exits 2" 2 '' '' -- report "$work/missing.nc" -o "$work/m.html"
holds "a missing program writes no page" test ! -e "$work/m.html"

# The line page (docs/report.md "The line page", docs/lines.md "ncsim line report"): one page for
# a production line, its summary the very object of `line time --json`, a run report per channel.
line=$programs/lines/two_pickers/line.toml
expect "line report exits 0 and prints where the page is" 0 "^report: $work/line\.html\$" '' -- \
  line report "$line" -o "$work/line.html"
holds "the line page is a line page" grep -q '<script type="application/json" id="ncsim-data">{"kind":"line",' \
  "$work/line.html"
holds "no temporary file is left beside the line page" no_temp "$work/line.html"
json=$("$ncsim" line time --json "$line")
holds "the line page's summary is line time --json's, to the byte" \
  grep -qF "\"summary\":$json,\"belt\":true," "$work/line.html"
holds "the line page has each channel's run report, in channel order" \
  grep -qE '"runs":\[\{"program":"[^"]*picker_up\.nc","machine":"delta_encoder".*\},\{"program":"[^"]*picker_down\.nc",' \
  "$work/line.html"
holds "each channel's part of the line page has its conveyor series" \
  test "$(grep -o '{"name":"belt_v_filtered"' "$work/line.html" | wc -l)" -eq 2
expect "a line report rerun exits 0" 0 '' '' -- line report "$line" -o "$work/line2.html"
same "line reports rerun byte-identically" "$work/line.html" "$work/line2.html"
mkdir -p "$work/csv1" "$work/csv2"
expect "line run --report writes the CSVs and names the page on stderr" 0 '' "^report: $work/line3\.html\$" \
  -- line run "$line" -o "$work/csv1" --report "$work/line3.html"
same "line run --report writes the page of line report" "$work/line.html" "$work/line3.html"
"$ncsim" line run "$line" -o "$work/csv2" >/dev/null 2>&1
for f in "$work/csv1"/*.csv; do
  same "line run --report leaves $(basename "$f") unchanged" "$f" "$work/csv2/$(basename "$f")"
done
expect "an unwritable line page exits 2 with NC8100 before the run" 2 '' \
  "the report: cannot write '$work/no/such/dir/l\.html': its folder '$work/no/such/dir' does not exist \[NC8100\]" -- \
  line report "$line" -o "$work/no/such/dir/l.html"
expect "line report without -o exits 2 with NC8101" 2 '' 'NC8101' -- line report "$line"
expect "--report on line time is refused, exit 2" 2 '' 'an option of line run' -- \
  line time "$line" --report "$work/x.html"
# A line whose channel waits for a signal that never comes (NC6401): the page still comes,
# exit 1, the channels' errors on it.
cat >"$work/a.nc" <<'NC'
%a
G01 X10 F6000
M30
NC
cat >"$work/b.nc" <<'NC'
%b
#WAIT SYN [ID1 CH1]
G01 Y10 F6000
M30
NC
cat >"$work/stuck.toml" <<'TOML'
[[channel]]
number = 1
program = "a.nc"
machine = "portal_3x"
[[channel]]
number = 2
program = "b.nc"
machine = "portal_3x"
TOML
expect "a line with a failing channel still writes its page, exit 1" 1 "^report: $work/stuck\.html\$" \
  'NC6401' -- line report "$work/stuck.toml" -o "$work/stuck.html"
holds "the failing channel's run is marked error on the page" \
  grep -q '"outcome":"error","stop":"","error":"[^"]*NC6401' "$work/stuck.html"
holds "a line without a belt: belt false" grep -q '"belt":false,' "$work/stuck.html"

summary "report cli"
