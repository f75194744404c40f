#!/usr/bin/env bash
# check_vs_rs274.sh [BLOCKS]
#
# Side-by-side check throughput on one core (taskset -c $CORE, default 1), on the same generated
# program (default 1,000,000 blocks, seed 1), against LinuxCNC's stand-alone `rs274` interpreter
# in batch mode (`rs274 -g`: its whole interpreter, canonical commands written to a file):
# - `ncsim check --syntax-only`: syntax and structure (issue 2's "syntax check");
# - `ncsim check --machine WIDE`: the full check, the interpreter run through the program with
#   every semantic check (issue 36), on a copy of machines/portal_3x with +-2 m software limits
#   (the generated coordinates leave its table; bench/big_programs.sh uses the same copy).
# Prints blocks/s for each (from CPU time, see run_timed), the ratios, and peak RSS. Targets
# (docs/benchmarks.md): syntax check >= 2,000,000 blocks/s and >= 10x rs274, full check >= 10x
# rs274, peak RSS < 150 MB. With STRICT=1 a missed target makes the exit status 1.
#
# Needs root for apt-get (package `time`, libboost-python1.74.0). LinuxCNC is not installed: its
# Debian package is downloaded and unpacked into $NCSIM_RS274_DIR (default /tmp/ncsim-rs274),
# never into the repository. Idempotent: what exists is reused; the program is regenerated
# (deterministic, same bytes every time). Environment: RUNS (default 3, best run counts),
# NCSIM_BUILD_DIR (a Release build with -DNCSIM_BENCH=ON; configured and built there when its
# ncsim or gen_program is missing), NCSIM_RS274_DIR, CORE, STRICT, SKIP_NCSIM=1 (rs274 alone).
set -euo pipefail

BLOCKS="${1:-1000000}"
RUNS="${RUNS:-3}"
CORE="${CORE:-1}"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${NCSIM_BUILD_DIR:-$REPO/build/release-bench}"
WORK="${NCSIM_RS274_DIR:-/tmp/ncsim-rs274}"
SEED=1

say() { printf '== %s\n' "$*" >&2; }
die() { printf 'check_vs_rs274: %s\n' "$*" >&2; exit 2; }

[[ "$BLOCKS" =~ ^[0-9]+$ && "$BLOCKS" -gt 0 ]] || die "BLOCKS must be a positive integer, got '$BLOCKS'"

# --- 1. packages ------------------------------------------------------------------------------
apt_install() {
  [[ "$(id -u)" == 0 ]] || die "need root to apt-get install $*"
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "$@" >&2
}
[[ -x /usr/bin/time ]] || apt_install time
command -v taskset >/dev/null || apt_install util-linux
dpkg -s libboost-python1.74.0 >/dev/null 2>&1 || apt_install libboost-python1.74.0

RS274="$WORK/root/usr/bin/rs274"
if [[ ! -x "$RS274" ]]; then
  say "fetching linuxcnc-uspace into $WORK"
  mkdir -p "$WORK/deb"
  (cd "$WORK/deb" && apt-get download linuxcnc-uspace >&2)
  deb="$(find "$WORK/deb" -name 'linuxcnc-uspace_*.deb' | sort | head -n 1)"
  rm -rf "$WORK/root"
  dpkg -x "$deb" "$WORK/root"
fi
export LD_LIBRARY_PATH="$WORK/root/usr/lib:$WORK/root/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# A one-tool table: rs274 wants one, the program never changes tools.
printf 'T1 P1 Z0 D0 ;bench tool\n' >"$WORK/tool.tbl"

# --- 2. ncsim Release build -------------------------------------------------------------------
NCSIM="$BUILD/cli/ncsim"
GEN="$BUILD/bench/gen_program"
if [[ ! -x "$NCSIM" || ! -x "$GEN" ]]; then
  say "building ncsim (Release) in $BUILD"
  cmake -S "$REPO" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DNCSIM_BENCH=ON >&2
  cmake --build "$BUILD" -j2 --target ncsim gen_program >&2
fi
# The full check's machine: portal_3x with +-2 m software limits.
WIDE="$WORK/portal_3x_wide"
rm -rf "$WIDE"
cp -r "$REPO/machines/portal_3x" "$WIDE"
sed -i 's/^kenngr.swe_pos .*/kenngr.swe_pos 20000000/; s/^kenngr.swe_neg .*/kenngr.swe_neg -20000000/' \
  "$WIDE"/x.lis "$WIDE"/y.lis "$WIDE"/z.lis

# --- 3. the program, both dialects ------------------------------------------------------------
say "generating $BLOCKS blocks (seed $SEED)"
"$GEN" --blocks "$BLOCKS" --seed "$SEED" --nc "$WORK/bench.nc" --ngc "$WORK/bench.ngc"

# --- 4. measurements --------------------------------------------------------------------------
# run_timed NAME CMD...: $RUNS runs on core $CORE. The time that counts is CPU time (user + system):
# on a shared machine other processes on core 0 stretch the wall time, not the CPU time. Sets
# BEST_S (least CPU time), BEST_WALL_S (least wall time), BEST_RSS_KB (largest peak RSS), RC.
run_timed() {
  local name="$1"
  shift
  BEST_S=""
  BEST_WALL_S=""
  BEST_RSS_KB=0
  local i log elapsed wall cpu rss
  for ((i = 1; i <= RUNS; i++)); do
    log="$WORK/time-$name-$i.log"
    set +e
    taskset -c "$CORE" /usr/bin/time -v -o "$log" "$@" >"$WORK/$name.stdout" 2>"$WORK/$name.stderr"
    RC=$?
    set -e
    elapsed="$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$log")"
    wall="$(awk -F: '{ s = 0; for (k = 1; k <= NF; k++) s = s * 60 + $k; printf "%.3f", s }' \
      <<<"$elapsed")"
    cpu="$(awk -F': ' '/User time \(seconds\)|System time \(seconds\)/ { s += $2 }
      END { printf "%.3f", s }' "$log")"
    rss="$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$log")"
    if [[ -z "$BEST_S" ]] || awk -v a="$cpu" -v b="$BEST_S" 'BEGIN { exit !(a < b) }'; then
      BEST_S="$cpu"
    fi
    if [[ -z "$BEST_WALL_S" ]] || awk -v a="$wall" -v b="$BEST_WALL_S" 'BEGIN { exit !(a < b) }'; then
      BEST_WALL_S="$wall"
    fi
    if ((rss > BEST_RSS_KB)); then BEST_RSS_KB="$rss"; fi
  done
}

say "rs274 -g ($RUNS runs)"
run_timed rs274 "$RS274" -g -t "$WORK/tool.tbl" "$WORK/bench.ngc" "$WORK/rs274.out"
RS_S="$BEST_S"
RS_WALL="$BEST_WALL_S"
RS_RSS="$BEST_RSS_KB"
RS_RC="$RC"
# rs274 -g prints errors on stdout/stderr and stops; a clean run ends with PROGRAM_END().
if ! grep -q 'PROGRAM_END()' "$WORK/rs274.out" || [[ "$RS_RC" != 0 ]]; then
  tail -n 5 "$WORK/rs274.stdout" "$WORK/rs274.stderr" >&2 || true
  die "rs274 did not reach the program end (exit $RS_RC): the .ngc program is not accepted"
fi

if [[ "${SKIP_NCSIM:-0}" == 1 ]]; then
  awk -v n="$BLOCKS" -v t="$RS_S" -v w="$RS_WALL" -v m="$RS_RSS" 'BEGIN {
    printf "linuxcnc rs274 -g: %d blocks in %.3f s CPU (%.3f s wall) = %.0f blocks/s, peak RSS %.1f MB\n",
      n, t, w, n / t, m / 1024 }'
  exit 0
fi
# ncsim_timed NAME CMD...: run_timed, and the check must pass (exit 0).
ncsim_timed() {
  local name="$1"
  shift
  run_timed "$name" "$@"
  if [[ "$RC" != 0 ]]; then
    head -n 20 "$WORK/$name.stderr" >&2 || true
    die "$* exited $RC: the generated .nc program is not clean"
  fi
}
say "ncsim check --syntax-only ($RUNS runs)"
ncsim_timed ncsim "$NCSIM" check --syntax-only "$WORK/bench.nc"
NC_S="$BEST_S" NC_WALL="$BEST_WALL_S" NC_RSS="$BEST_RSS_KB"
say "ncsim check --machine portal_3x_wide ($RUNS runs)"
ncsim_timed ncsim-full "$NCSIM" check --machine "$WIDE" "$WORK/bench.nc"
FULL_S="$BEST_S" FULL_WALL="$BEST_WALL_S" FULL_RSS="$BEST_RSS_KB"

# --- 5. table ---------------------------------------------------------------------------------
awk -v n="$BLOCKS" -v rs="$RS_S" -v rsw="$RS_WALL" -v rsm="$RS_RSS" -v nc="$NC_S" \
  -v ncw="$NC_WALL" -v ncm="$NC_RSS" -v fu="$FULL_S" -v fuw="$FULL_WALL" -v fum="$FULL_RSS" \
  -v strict="${STRICT:-0}" -v load="$(cut -d' ' -f1-3 /proc/loadavg)" '
  function rate(t) { return t > 0 ? n / t : 0 }
  function row(name, t, w, m) {
    printf "%-30s %10d %9.3f %9.3f %12.0f %14.1f\n", name, n, t, w, rate(t), m / 1024
  }
  BEGIN {
    r_rs = rate(rs); r_nc = rate(nc); r_fu = rate(fu)
    ratio = r_rs > 0 ? r_nc / r_rs : 0; ratio_full = r_rs > 0 ? r_fu / r_rs : 0
    printf "\n%-30s %10s %9s %9s %12s %14s\n", "1 core", "blocks", "CPU [s]", "wall [s]",
      "blocks/s", "peak RSS [MB]"
    row("ncsim check --syntax-only", nc, ncw, ncm)
    row("ncsim check (full, machine)", fu, fuw, fum)
    row("linuxcnc rs274 -g", rs, rsw, rsm)
    printf "%-30s %10s %9s %9s %11.1fx\n", "ratio syntax check / rs274", "", "", "", ratio
    printf "%-30s %10s %9s %9s %11.1fx\n", "ratio full check / rs274", "", "", "", ratio_full
    printf "(blocks/s from the least CPU time, user + system, of the runs; load %s)\n\n", load
    ok1 = r_nc >= 2000000; ok2 = ratio >= 10; ok3 = ratio_full >= 10
    ok4 = ncm / 1024 < 150 && fum / 1024 < 150
    printf "target syntax check >= 2,000,000 blocks/s : %s\n", ok1 ? "met" : "MISSED"
    printf "target syntax check >= 10x rs274          : %s\n", ok2 ? "met" : "MISSED"
    printf "target full check >= 10x rs274            : %s\n", ok3 ? "met" : "MISSED"
    printf "target peak RSS < 150 MB                  : %s\n", ok4 ? "met" : "MISSED"
    exit (strict && !(ok1 && ok2 && ok3 && ok4)) ? 1 : 0
  }'
