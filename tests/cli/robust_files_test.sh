#!/usr/bin/env bash
# robust_files_test.sh NCSIM FIXTURES: issue 34's file, output and signal defects. Inputs that
# are no regular files are refused at once (a list that is a pipe or /dev/zero); outputs never
# replace a pipe, a device or a symlink and never share a temporary name; a signal or a closed
# pipe leaves no temporary file and ends with a message. Every ncsim call is bounded in time
# (a hang is a failure, exit 124), FIFOs and children are cleaned up at exit.
set -uo pipefail
real_ncsim=$1
fixtures=$2
root=$(cd "$fixtures/../.." && pwd)
work=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT
# Every call ends within 20 s (timeout's status 124 fails the check that expects another).
ncsim=$work/ncsim
printf '#!/usr/bin/env bash\nexec timeout -k 5 20 %q "$@"\n' "$real_ncsim" >"$ncsim"
chmod +x "$ncsim"

# expect, again, same, holds, summary: tests/cli/expect.sh.
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"
long_line=$fixtures/long_line.nc

# ---- item 8: a list that is no regular file --------------------------------------------------
# machine_with NAME FILE: portal_3x in $work/NAME whose X list is FILE (a symlink to it).
machine_with() {
  cp -r "$root/machines/portal_3x" "$work/$1"
  rm "$work/$1/x.lis"
  ln -s "$2" "$work/$1/x.lis"
  echo "$work/$1"
}
mkfifo "$work/fifo.lis"
expect "an axis list that is a pipe is refused at once (NC3010), not read" 2 '' \
  "machine\.lis:4:1: error: cannot read list '.*x\.lis': not a regular file \(a pipe\) \[NC3010\]" -- \
  check --machine "$(machine_with m_fifo "$work/fifo.lis")" "$long_line"
expect "an axis list that is /dev/zero is refused at once (NC3010), memory stays flat" 2 '' \
  "cannot read list '.*x\.lis': not a regular file \(a device\) \[NC3010\]" -- \
  check --machine "$(machine_with m_zero /dev/zero)" "$long_line"
cp -r "$root/machines/portal_3x" "$work/m_chfifo"
rm "$work/m_chfifo/channel.lis"
mkfifo "$work/m_chfifo/channel.lis"
expect "a channel list that is a pipe is refused at once (NC3010)" 2 '' \
  "cannot read list '.*channel\.lis': not a regular file \(a pipe\) \[NC3010\]" -- \
  time --machine "$work/m_chfifo" "$long_line"
cp -r "$root/machines/portal_3x" "$work/m_big"
truncate -s 17M "$work/m_big/y.lis"
expect "a list over 16 MiB is refused (NC3010), not read" 2 '' \
  "cannot read list '.*y\.lis': 17825792 bytes, above the limit of 16 MiB \[NC3010\]" -- \
  check --machine "$work/m_big" "$long_line"
cp -r "$root/machines/portal_3x" "$work/m_idx"
rm "$work/m_idx/machine.lis"
mkfifo "$work/m_idx/machine.lis"
expect "a machine index that is a pipe is refused at once (NC3010)" 2 '' \
  "machine\.lis: error: cannot read the machine index: not a regular file \(a pipe\) \[NC3010\]" -- \
  check --machine "$work/m_idx" "$long_line"
mkfifo "$work/scenario_fifo.toml"
expect "a scenario that is a pipe is refused at once, named as such" 2 '' \
  "cannot read the scenario '.*scenario_fifo\.toml': not a regular file \(a pipe\)" -- \
  time --scenario "$work/scenario_fifo.toml" "$long_line"

# ---- items 9, 10, 26: outputs (core/output_file, docs/design.md "Output files") -----------
mkfifo "$work/page.fifo"
timeout 20 cat "$work/page.fifo" >"$work/from_fifo" &
pids+=($!)
expect "report -o a pipe writes the page into the pipe (a stream, in place)" 0 '' '' -- \
  report "$fixtures/clean.nc" -o "$work/page.fifo"
wait "${pids[-1]}"
holds "report -o a pipe: the pipe is still a pipe" test -p "$work/page.fifo"
holds "report -o a pipe: the reader got the page" grep -q '</html>' "$work/from_fifo"
mkdir "$work/runs"
printf 'old\n' >"$work/runs/r1.html"
ln -s runs/r1.html "$work/latest.html"
expect "report -o a symlink writes through the link" 0 '' '' -- \
  report "$fixtures/clean.nc" -o "$work/latest.html"
holds "report -o a symlink: the link stays a link" test -L "$work/latest.html"
holds "report -o a symlink: its target holds the page" grep -q '</html>' "$work/runs/r1.html"
expect "report -o a directory is refused before the run (NC8100)" 2 '' \
  "ncsim: error: the report: cannot write '$work/runs': it is a directory, not a file an output may replace \[NC8100\]" -- \
  report "$fixtures/clean.nc" -o "$work/runs"
expect "run -o '' is refused before the run (NC9150)" 2 '' \
  '^ncsim: error: an output needs a file name \(an empty name was given\) \[NC9150\]$' -- \
  run -o '' "$long_line"
holds "run -o '': no file made in the working folder" test ! -e .tmp
expect "run --report into a missing folder says why, before the run (NC8100)" 2 '' \
  "the report: cannot write '$work/nodir/r\.html': its folder '$work/nodir' does not exist \[NC8100\]" -- \
  run -o "$work/never.csv" --report "$work/nodir/r.html" "$long_line"
holds "run --report refused: the CSV was not written either" test ! -e "$work/never.csv"
expect "run -o into /sys (no file can be created there) says why (NC9150)" 2 '' \
  "cannot write '/sys/x\.csv': cannot create a file in its folder '/sys': Permission denied \[NC9150\]" -- \
  run -o /sys/x.csv "$long_line"
holds "no temporary file in the working folder" bash -c '! ls ./*.tmp >/dev/null 2>&1'

# Two runs writing the same -o at once: each writes its own temporary file; the result is one
# complete run (never a mix), no temporary file is left.
"$ncsim" run -o "$work/ref.csv" "$long_line" 2>/dev/null
for k in 1 2 3 4; do
  "$ncsim" run -o "$work/same.csv" "$long_line" 2>/dev/null &
  pids+=($!)
done
both=0
for k in 1 2 3 4; do wait "${pids[-k]}" || both=1; done
holds "four runs to the same -o at once all exit 0" test "$both" -eq 0
same "four runs to the same -o at once: the file is one complete run" "$work/ref.csv" "$work/same.csv"
holds "four runs to the same -o at once: no temporary file left" \
  bash -c "! ls '$work'/same.csv.*.tmp >/dev/null 2>&1"

# ---- item 13: a signal during run -o / golden bless leaves no temporary file ---------------
# slow.nc: 700 mm at 1 mm/s, 700,000 cycles: seconds of CSV writing.
printf '%%slow\nN10 G01 X700 F60\nN20 M30\n' >"$work/slow.nc"
# wait_for GLOB: a file matching GLOB exists within 10 s.
wait_for() {
  for _ in $(seq 100); do
    compgen -G "$1" >/dev/null && return 0
    sleep 0.1
  done
  return 1
}
# bounded_pid PIDFILE ARGS...: ncsim ARGS, bounded by timeout(1), its own pid written to PIDFILE.
# The signal goes to ncsim itself: timeout(1) of coreutils 9.1 installs its handlers before its
# fork() and, signalled before it is back from it, takes itself for the child and exits, leaving
# ncsim running (a run here now and then went on writing after the test's check).
bounded_pid() {
  local pidfile=$1
  shift
  timeout -k 5 20 bash -c 'echo $$ >"$0"; exec "$@"' "$pidfile" "$real_ncsim" "$@"
}
# signal_ncsim SIG PIDFILE: sends SIG to the ncsim whose pid PIDFILE holds (waits for the file).
signal_ncsim() {
  for _ in $(seq 100); do
    [[ -s $2 ]] && break
    sleep 0.1
  done
  kill -s "$1" "$(cat "$2")"
}
for sig in INT TERM HUP; do
  rm -f "$work/sig.csv" "$work/sig.pid"
  # ncsim runs under bash -c in timeout(1), whose SIGINT is not ignored (as a background child
  # of this shell's would be).
  bounded_pid "$work/sig.pid" run -o "$work/sig.csv" "$work/slow.nc" 2>/dev/null &
  pid=$!
  pids+=($pid)
  holds "SIG$sig: the run's temporary file appears" wait_for "$work/sig.csv.*.tmp"
  signal_ncsim "$sig" "$work/sig.pid"
  wait "$pid" 2>/dev/null
  status=$?
  holds "SIG$sig during run -o: the run ends by the signal (status $status)" test "$status" -ne 0 -a "$status" -ne 124
  holds "SIG$sig during run -o: no temporary file left" bash -c "! ls '$work'/sig.csv.*.tmp >/dev/null 2>&1"
  holds "SIG$sig during run -o: no output file made" test ! -e "$work/sig.csv"
done
mkdir -p "$work/lib/slow" "$work/tmp"
cp "$work/slow.nc" "$work/lib/slow/slow.nc"
rm -f "$work/bless.pid"
TMPDIR=$work/tmp bounded_pid "$work/bless.pid" golden bless "$work/lib/slow" >/dev/null 2>&1 &
pid=$!
pids+=($pid)
holds "golden bless: the run's temporary CSV appears" wait_for "$work/tmp/ncsim-golden-*"
signal_ncsim TERM "$work/bless.pid"
wait "$pid" 2>/dev/null
holds "SIGTERM during golden bless: no temporary CSV left" test -z "$(ls -A "$work/tmp")"
holds "SIGTERM during golden bless: no golden, no temporary golden" test -z "$(ls "$work/lib/slow" | grep -v '^slow\.nc$')"
# A golden that cannot be written is found before the run, with the reason: a folder nothing can
# be created in (root writes anywhere, so there a directory stands where the golden would).
mkdir -p "$work/ro/slow"
cp "$work/slow.nc" "$work/ro/slow/slow.nc"
if [[ $(id -u) -eq 0 ]]; then
  mkdir "$work/ro/slow/slow.golden"
  why="it is a directory, not a file an output may replace"
else
  chmod a-w "$work/ro/slow"
  why="cannot create a file in its folder '$work/ro/slow': Permission denied"
fi
TMPDIR=$work/tmp expect "golden bless of a golden that cannot be written says why, before the run (NC8009)" 2 '' \
  "ro/slow: error: cannot write '$work/ro/slow/slow\.golden': $why; nothing blessed \[NC8009\]" -- \
  golden bless "$work/ro/slow"
holds "golden bless refused: no run was made (no temporary CSV)" test -z "$(ls -A "$work/tmp")"
chmod u+w "$work/ro/slow"

# ---- item 16: a closed pipe is a write error, exit 2 with a message ------------------------
# closed_pipe NAME ARGS...: ncsim writes into a pipe whose reader has already gone.
closed_pipe() {
  local name=$1
  shift
  exec {w}> >(exit 0)
  wait $! 2>/dev/null
  "$ncsim" "$@" >&$w 2>"$work/err"
  local status=$?
  exec {w}>&-
  checks=$((checks + 1))
  if [[ $status -eq 2 ]] && grep -Eq 'cannot write' "$work/err"; then
    echo "ok   $name"
  else
    failures=$((failures + 1))
    echo "FAIL $name: exit $status (want 2)"
    sed 's/^/  stderr: /' "$work/err"
  fi
}
closed_pipe "run -o - into a closed pipe: exit 2, a message" run -o - "$long_line"
closed_pipe "time --blocks into a closed pipe: exit 2, a message" time --blocks "$long_line"
closed_pipe "trace into a closed pipe: exit 2, a message" trace "$long_line"
closed_pipe "check into a closed pipe: exit 2, a message" check "$long_line"
closed_pipe "golden check into a closed pipe: exit 2, a message" golden check "$root/programs/isg_reference_example"

# ---- item 20: a syntax error in an L file is positioned by time and run as by check --------
mkdir "$work/lsub"
printf '%%lmain\nG01 X1 F600\nL sub_bad.nc\nM30\n' >"$work/lsub/lmain.nc"
cp "$root/interp/testdata/sub_bad.nc" "$work/lsub/"
"$ncsim" check "$work/lsub/lmain.nc" >/dev/null 2>"$work/check_err"
syntax=$(grep -E 'sub_bad\.nc:[0-9]+:[0-9]+: error: .*\[NC[0-9]+\]$' "$work/check_err" | head -1)
holds "check positions the L file's syntax error (file:line:col)" test -n "$syntax"
for cmd in time run; do
  expect "$cmd stops at the call of an L file with a syntax error (NC4306), status 1" 1 '' 'NC4306' -- \
    $cmd "$work/lsub/lmain.nc"
  holds "$cmd positions the L file's syntax error as check does" grep -qF -- "$syntax" "$work/err"
done

summary robust_files_test
