#!/usr/bin/env bash
# report/cli_test.sh NCSIM FIXTURES: end-to-end checks of `ncsim report` and `run --report`
# (docs/report.md): exit statuses, the page written atomically and byte-identical on reruns,
# the same page from `run --report` with the CSV unchanged, the outcome of a failed or stopped
# run on the page, write errors with their ids.
set -uo pipefail
ncsim=$1
fixtures=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() {  # check NAME CONDITION...: evaluates the condition (a command)
  local name=$1
  shift
  if "$@"; then
    echo "ok   $name"
  else
    echo "FAIL $name"
    failures=$((failures + 1))
  fi
}
status_of() {  # status_of ARGS...: ncsim's exit status, output in $work/out, $work/err
  "$ncsim" "$@" >"$work/out" 2>"$work/err" </dev/null
  echo $?
}

s=$(status_of report "$fixtures/clean.nc" -o "$work/a.html")
check "report exits 0 and names the page" test "$s" -eq 0 -a -s "$work/a.html"
check "report prints where the page is" grep -q "^report: $work/a.html\$" "$work/out"
check "no temporary file is left" test ! -e "$work/a.html.tmp"
check "the page inlines uPlot" grep -q 'uPlot (v1\.6\.32)' "$work/a.html"
check "the page says the run was ok" grep -q '"outcome":"ok"' "$work/a.html"
status_of report "$fixtures/clean.nc" -o "$work/b.html" >/dev/null
check "reruns are byte-identical" cmp -s "$work/a.html" "$work/b.html"

status_of run "$fixtures/clean.nc" -o "$work/plain.csv" >/dev/null
s=$(status_of run "$fixtures/clean.nc" -o "$work/with.csv" --report "$work/c.html")
check "run --report exits 0" test "$s" -eq 0
check "run --report names the page on stderr" grep -q "^report: $work/c.html\$" "$work/err"
check "run --report writes the page of report" cmp -s "$work/a.html" "$work/c.html"
check "run --report leaves the CSV unchanged" cmp -s "$work/plain.csv" "$work/with.csv"

s=$(status_of report "$fixtures/soft_limit.nc" -o "$work/soft.html")
check "a run-time error still writes the page, exit 1" test "$s" -eq 1 -a -s "$work/soft.html"
check "the page shows the outcome and the error id" \
  grep -q '"outcome":"error".*NC5502' "$work/soft.html"
check "the error is on stderr as run prints it" grep -q 'run-time error at t=8\.018 s' "$work/err"

s=$(status_of report "$fixtures/ve_branch.nc" --scenario "$fixtures/scenario_stop.toml" \
  -o "$work/stop.html")
check "a scenario stop writes the page, exit 0" test "$s" -eq 0
check "the page shows the stop reason" grep -q '"outcome":"stopped","stop":"[^"]' "$work/stop.html"

s=$(status_of report "$fixtures/clean.nc" -o "$work/no/such/dir/x.html")
check "an unwritable page exits 2 with NC8100" test "$s" -eq 2
check "NC8100 names the file" grep -q "cannot write the report '$work/no/such/dir/x.html.tmp' \[NC8100\]" "$work/err"
s=$(status_of report "$fixtures/clean.nc" -o "")
check "an empty -o exits 2 with NC8101" test "$s" -eq 2
check "NC8101 is printed" grep -q 'NC8101' "$work/err"
s=$(status_of report "$work/missing.nc" -o "$work/m.html")
check "a missing program exits 2, no page" test "$s" -eq 2 -a ! -e "$work/m.html"

echo "report cli: $failures failed"
((failures == 0))
