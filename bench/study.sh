#!/usr/bin/env bash
# bench/study.sh [NCSIM]: a 100-run study on this machine's cores against its runs one after
# another (issue 37: "a 100-run study on this machine's 2 cores takes less than 60 % of running
# its runs one after another"). The study: programs/lines/two_pickers (two delta pickers, 20 s
# of line each) at 5 belt velocities x 20 seeds of its random workpiece stream. Wall time of
# `ncsim study run --jobs 1` (the runs one after another, in one process) and of `--jobs J`
# (default: the cores); both tables must be byte-identical. Prints both wall times, the ratio,
# each run's CPU time (user + system) and the share of a core it got (CPU / wall), the cores and
# the load average before and after. The machine may be shared: wall time is what a study
# costs, and on a busy machine the kernel's fair share per session (autogroup) caps what a
# second thread can add, which the share of a core shows. Exit 1 when the ratio is 0.6 or more.
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
NCSIM="${1:-${NCSIM_BUILD_DIR:-$REPO/build/release}/cli/ncsim}"
JOBS="${JOBS:-$(nproc)}"
WORK=$(mktemp -d /tmp/ncsim-study-bench.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
cat >"$WORK/study.toml" <<TOML
description = "bench/study.sh: two_pickers, 5 belt velocities x 20 stream seeds"
line = "$REPO/programs/lines/two_pickers/line.toml"
[vary]
belt_velocity = { from = 260, to = 340, step = 20 }
seed = { from = 1, to = 20 }
TOML
wall() {  # wall DIR JOBS: prints "WALL CPU" [s] of one study run (CPU: user + system, wait4)
  python3 - "$NCSIM" study run "$WORK/study.toml" -o "$WORK/$1" --jobs "$2" <<'PY'
import os, subprocess, sys, time
t0 = time.monotonic()
p = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL)
_, status, ru = os.wait4(p.pid, 0)
wall = time.monotonic() - t0
if status != 0:
    sys.exit(f"study: {' '.join(sys.argv[1:])} failed ({status})")
print(f"{wall:.2f} {ru.ru_utime + ru.ru_stime:.2f}")
PY
}
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
read -r one one_cpu < <(wall one 1)
read -r many many_cpu < <(wall many "$JOBS")
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
cmp -s "$WORK/one/results.csv" "$WORK/many/results.csv" || {
  echo "study: the tables of --jobs 1 and --jobs $JOBS differ" >&2
  exit 1
}
rows=$(($(wc -l <"$WORK/one/results.csv") - 1))
python3 - "$one" "$many" "$one_cpu" "$many_cpu" "$JOBS" "$rows" "$(nproc)" "$load_before" \
  "$load_after" <<'PY'
import sys
one, many, one_cpu, many_cpu = (float(x) for x in sys.argv[1:5])
jobs, rows, cores, before, after = sys.argv[5:]
ratio = many / one
print(f"study: {rows} runs, one after another {one:.2f} s wall ({one_cpu:.2f} s CPU, "
      f"{100 * one_cpu / one:.0f} % of a core), --jobs {jobs} {many:.2f} s wall ({many_cpu:.2f} s "
      f"CPU, {100 * many_cpu / many:.0f} % of a core): {100 * ratio:.0f} % (target < 60 %: "
      f"{'met' if ratio < 0.6 else 'MISSED'}); {cores} cores, load {before} before, {after} "
      f"after; tables identical")
sys.exit(0 if ratio < 0.6 else 1)
PY
