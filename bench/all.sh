#!/usr/bin/env bash
# bench/all.sh [ROW...]: the rows of docs/benchmarks.md, each measured by one command.
#
#   bash bench/all.sh            every row, in the table's order
#   bash bench/all.sh ROW...     only these rows (e.g. `bash bench/all.sh dense-walk`)
#   bash bench/all.sh --list     the rows and what each measures
#
# Needs a Release build with -DNCSIM_BENCH=ON in $NCSIM_BUILD_DIR (default build/release):
#   bash scripts/build.sh build/release -DCMAKE_BUILD_TYPE=Release -DNCSIM_BENCH=ON
# and /usr/bin/time (package `time`). Speed rows run pinned to core $CORE (default 1) and count
# CPU time (user + system; the least and the median of $RUNS runs, default 3), never wall time:
# the machine may be shared. Every row prints the load average it ran at. Generated programs
# go to $NCSIM_BENCH_DIR (default /tmp/ncsim-bench), never into the repository.
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${NCSIM_BUILD_DIR:-$REPO/build/release}"
WORK="${NCSIM_BENCH_DIR:-/tmp/ncsim-bench}"
RUNS="${RUNS:-3}"
export CORE="${CORE:-1}"
NCSIM="$BUILD/cli/ncsim"
PY=/usr/bin/python3
[[ -x $PY ]] || PY=python3
CPU=("$PY" "$REPO/bench/cpu.py" --runs "$RUNS")
GBENCH=("$PY" "$REPO/bench/gbench.py" --reps "$RUNS")

ROWS=(grammar interp axes planner ipo rs274 big big-5gb dense-walk dense-cam chords-10m run-csv
  move200 report blend bound checker line line-cost line-seeds study)
describe() {
  case $1 in
    grammar) echo "grammar_bench: check_program in memory, blocks/s" ;;
    interp) echo "interp_bench: generated program to commands, \$FOR iterations/s" ;;
    axes) echo "axes_bench: PTP plans/s (rest to rest, from moving starts), Profile::at" ;;
    planner) echo "planner_bench: look-ahead segments/s, preparation, profiles, splines" ;;
    ipo) echo "ipo_bench: the time loop in x real time (in memory)" ;;
    rs274) echo "check_vs_rs274.sh: ncsim check (syntax, full) against LinuxCNC rs274, 1 M blocks" ;;
    big) echo "big_programs.sh 10000000: check / trace of 10 M blocks, peak RSS" ;;
    big-5gb) echo "big_programs.sh 130000000: the same on 5.1 GB (5 GB of /tmp, ~10 min)" ;;
    dense-walk) echo "ncsim time, 200,000 chords of 0.1 mm, +-1.7 deg, G261 PATH_DEV 0.01" ;;
    dense-cam) echo "ncsim time programs/dense_cam, as bundled and with G261 PATH_DEV 0.01" ;;
    chords-10m) echo "ncsim time, 10,000,000 chords of 0.1 mm: x real time, peak RSS" ;;
    run-csv) echo "ncsim run -o FILE.csv: 100,000 chords and programs/move200" ;;
    move200) echo "ncsim time programs/move200; move200_bound: the 200-move table" ;;
    report) echo "ncsim report on a 671 s run; the page drawn in headless Chromium" ;;
    blend) echo "blend_set.py: G261 / G260 / G60 on seeded 200-move programs (simulated s)" ;;
    bound) echo "bound.py: G261 against the time-optimal bound, seeds 1..4 (simulated s)" ;;
    checker) echo "checker_set.sh 151..1150: the trajectory checker over 1000 programs" ;;
    line) echo "line_accuracy.sh: conveyor tracking contour error (deterministic)" ;;
    line-cost) echo "line_cost.sh: ncsim line time, two channels against each alone (CPU)" ;;
    line-seeds) echo "line_seeds.sh 200: the two-picker line over 200 seeded streams, counts closed" ;;
    study) echo "study.sh: a 100-run study, --jobs \$(nproc) against one after another (wall)" ;;
    *) return 1 ;;
  esac
}

need() {
  local f
  for f in "$@"; do
    [[ -x "$BUILD/$f" ]] || {
      echo "bench/all.sh: $BUILD/$f missing: build with -DCMAKE_BUILD_TYPE=Release -DNCSIM_BENCH=ON" >&2
      exit 2
    }
  done
}

# sim PROGRAM [ncsim options]: the simulated seconds of `ncsim time`.
sim() {
  "$NCSIM" time --json "$@" | "$PY" -c 'import json, sys; print(json.load(sys.stdin)["total_s"])'
}

# walk FILE [dense_chords.py walk options]: write the chord walk once.
walk() {
  local file=$1
  shift
  [[ -s "$file" ]] || "$PY" "$REPO/bench/dense_chords.py" walk "$@" >"$file"
}

row_grammar() { need bench/grammar_bench && "${GBENCH[@]}" "$BUILD/bench/grammar_bench"; }
row_interp() { need bench/interp_bench && "${GBENCH[@]}" "$BUILD/bench/interp_bench"; }
row_axes() { need bench/axes_bench && "${GBENCH[@]}" "$BUILD/bench/axes_bench"; }
row_planner() { need bench/planner_bench && "${GBENCH[@]}" "$BUILD/bench/planner_bench"; }
row_ipo() { need bench/ipo_bench && "${GBENCH[@]}" "$BUILD/bench/ipo_bench"; }
row_rs274() { NCSIM_BUILD_DIR="$BUILD" RUNS="$RUNS" bash "$REPO/bench/check_vs_rs274.sh"; }
row_big() { NCSIM_BUILD_DIR="$BUILD" bash "$REPO/bench/big_programs.sh" 10000000; }
row_big-5gb() { NCSIM_BUILD_DIR="$BUILD" bash "$REPO/bench/big_programs.sh" 130000000; }

row_dense-walk() {
  need cli/ncsim
  local p="$WORK/walk_g261.nc"
  walk "$p"
  "${CPU[@]}" --label "time, 200,000 chords +-1.7 deg, G261 0.01" --sim-json --target-x 500 \
    -- "$NCSIM" time --json "$p"
  p="$WORK/walk_g260.nc"
  walk "$p" --path-dev 0
  "${CPU[@]}" --label "time, the same chords at G260 (VELOJUMP)" --sim-json \
    -- "$NCSIM" time --json "$p"
}

row_dense-cam() {
  need cli/ncsim
  local m="$REPO/machines/portal_3x" p="$WORK/dense_cam_g261.nc"
  "${CPU[@]}" --label "time programs/dense_cam (G260)" --sim-json --target-x 500 \
    -- "$NCSIM" time --json --machine "$m" "$REPO/programs/dense_cam/dense_cam.nc"
  sed 's/^N10 G17 G90 G71 G94$/&\n#CONTOUR MODE [DEV, PATH_DEV=0.01]\nG261/' \
    "$REPO/programs/dense_cam/dense_cam.nc" >"$p"
  "${CPU[@]}" --label "time programs/dense_cam with G261 0.01" --sim-json --target-x 500 \
    -- "$NCSIM" time --json --machine "$m" "$p"
}

row_chords-10m() {
  need cli/ncsim
  local p="$WORK/circle_10M.nc"
  [[ -s "$p" ]] || "$PY" "$REPO/bench/dense_chords.py" circle --chords 10000000 >"$p"
  "${CPU[@]}" --label "time, 10,000,000 chords (circle)" --sim-json --target-x 500 \
    --target-mb 64 -- "$NCSIM" time --json "$p"
}

row_run-csv() {
  need cli/ncsim
  local p="$WORK/circle_100k.nc" m200="$REPO/programs/move200/move200.nc"
  [[ -s "$p" ]] || "$PY" "$REPO/bench/dense_chords.py" circle --chords 100000 >"$p"
  "${CPU[@]}" --label "run -o CSV, 100,000 chords (circle)" --sim "$(sim "$p")" --target-x 300 \
    --target-mb 64 -- "$NCSIM" run -o "$WORK/circle_100k.csv" "$p"
  "${CPU[@]}" --label "run -o CSV, programs/move200" --sim "$(sim "$m200")" --target-x 300 \
    -- "$NCSIM" run -o "$WORK/move200.csv" "$m200"
}

row_move200() {
  need cli/ncsim bench/move200_bound
  "${CPU[@]}" --label "time programs/move200 (whole process)" --sim-json --target-x 2000 \
    -- "$NCSIM" time --json "$REPO/programs/move200/move200.nc"
  "$BUILD/bench/move200_bound"
}

# The program of docs/report.md "Figures": 75 passes of a rectangle, 671 s.
row_report() {
  need cli/ncsim
  local p="$WORK/ten_minutes.nc" page="$WORK/ten_minutes.html" browser k
  sed -n '/^    ; ten_minutes/,/^    N100 M30/s/^    //p' "$REPO/docs/report.md" >"$p"
  "${CPU[@]}" --label "report -o page.html, 671 s run" --sim "$(sim "$p")" \
    -- "$NCSIM" report "$p" -o "$page"
  echo "page: $(stat -c %s "$page") bytes"
  browser=$(command -v chromium || command -v chromium-browser || true)
  [[ -n $browser ]] || { echo "(no chromium: the page's drawing time is not measured)"; return; }
  for k in 1 2 3; do
    # data-ms: performance.now() when the last chart has drawn (report/page.js); target < 2 s.
    timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage \
      --user-data-dir="$WORK/chromium" --window-size=1280,900 --dump-dom "file://$page" \
      2>/dev/null | grep -o '<div id="ncsim-status"[^>]*>' |
      sed -E 's/.*data-state="([a-z]*)".*data-drawn="([0-9]+)".*data-ms="([0-9]+)".*/Chromium: \1, \2 charts drawn in \3 ms (target < 2000 ms)/'
  done
}

row_blend() {
  need cli/ncsim
  "$PY" "$REPO/bench/blend_set.py" --ncsim "$NCSIM" --seeds 1..4 --out "$WORK/blend_set"
}

row_bound() {
  need cli/ncsim
  local seed jerk out="$WORK/blend_set"
  [[ -s "$out/s4_G261.nc" ]] || "$PY" "$REPO/bench/blend_set.py" --ncsim "$NCSIM" --seeds 1..4 \
    --out "$out" >/dev/null
  for jerk in 100000 1e+09; do
    for seed in 1 2 3 4; do
      echo "-- seed $seed, J $jerk"
      "$PY" "$REPO/bench/bound.py" "$out/s${seed}_G261.nc" --machine "$out/machine_j$jerk" \
        --from-line 7 --ncsim "$NCSIM"
    done
  done
}

row_checker() {
  need cli/ncsim
  CHECKER_OUT="$WORK/checker" bash "$REPO/bench/checker_set.sh" "$NCSIM" 151..1150 "$(nproc)" |
    tail -n 30 || true
}

row_line() { need cli/ncsim && bash "$REPO/bench/line_accuracy.sh" "$NCSIM"; }
row_line-cost() { need cli/ncsim && RUNS="$RUNS" bash "$REPO/bench/line_cost.sh" "$NCSIM"; }
row_line-seeds() { need cli/ncsim && NCSIM_BUILD_DIR="$BUILD" bash "$REPO/bench/line_seeds.sh" 200; }
row_study() { need cli/ncsim && bash "$REPO/bench/study.sh" "$NCSIM"; }

if [[ "${1:-}" == --list ]]; then
  for r in "${ROWS[@]}"; do printf '%-11s %s\n' "$r" "$(describe "$r")"; done
  exit 0
fi
[[ -x /usr/bin/time ]] || { echo "bench/all.sh: needs /usr/bin/time (apt-get install time)" >&2; exit 2; }
mkdir -p "$WORK"
selected=("$@")
[[ ${#selected[@]} -gt 0 ]] || selected=("${ROWS[@]}")
for r in "${selected[@]}"; do
  describe "$r" >/dev/null || { echo "bench/all.sh: no row '$r' (--list)" >&2; exit 2; }
done
echo "machine: $(nproc) x $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1); build $BUILD; core $CORE"
for r in "${selected[@]}"; do
  echo
  echo "== $r: $(describe "$r") (uptime:$(uptime | sed 's/.*load average//'))"
  "row_$r"
done
