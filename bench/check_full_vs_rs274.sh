#!/usr/bin/env bash
# check_full_vs_rs274.sh [BLOCKS]
#
# The full check against LinuxCNC's `rs274` on one core: `ncsim check --machine DIR prog.nc`
# (syntax, structure, then the interpreter runs the program without motion: semantics, soft
# limits, endless-loop detection) on the program bench/check_vs_rs274.sh generates (default
# 1,000,000 blocks, seed 1), against `rs274 -g` on the same program in RS274/NGC. Both must
# accept the program. Prints blocks/s from CPU time (user + system, least of $RUNS runs), the
# ratio and peak RSS. Target (issue 36): ncsim full check >= 10x rs274. STRICT=1: a missed
# target makes the exit status 1.
#
# Runs check_vs_rs274.sh with SKIP_NCSIM=1 first: it installs what is needed, downloads and
# unpacks rs274, builds gen_program and writes the program. Then ncsim and rs274 run in turn on
# the same core, so that both see the same machine load. The machine is a copy of machines/portal_3x with +-2 m
# software limits (the generated coordinates leave the 800 x 600 mm table), as in
# bench/big_programs.sh. Core: taskset -c $CORE (default 1). Environment as check_vs_rs274.sh
# (RUNS, NCSIM_BUILD_DIR, NCSIM_RS274_DIR, STRICT), plus CORE.
set -euo pipefail

BLOCKS="${1:-1000000}"
RUNS="${RUNS:-3}"
CORE="${CORE:-1}"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${NCSIM_BUILD_DIR:-$REPO/build/release-bench}"
WORK="${NCSIM_RS274_DIR:-/tmp/ncsim-rs274}"
export RUNS NCSIM_BUILD_DIR="$BUILD" NCSIM_RS274_DIR="$WORK"

say() { printf '== %s\n' "$*" >&2; }
die() { printf 'check_full_vs_rs274: %s\n' "$*" >&2; exit 2; }

# --- 1. rs274, the program (both dialects), gen_program ---------------------------------------
# (one rs274 run there: the figures that count are taken below, on the same core as ncsim's)
RUNS=1 SKIP_NCSIM=1 STRICT=0 bash "$REPO/bench/check_vs_rs274.sh" "$BLOCKS" >&2
RS274="$WORK/root/usr/bin/rs274"
export LD_LIBRARY_PATH="$WORK/root/usr/lib:$WORK/root/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

# --- 2. ncsim and the machine -----------------------------------------------------------------
say "building ncsim (Release) in $BUILD"
cmake --build "$BUILD" -j2 --target ncsim >&2
NCSIM="$BUILD/cli/ncsim"
machine="$WORK/portal_3x_wide"
rm -rf "$machine"
cp -r "$REPO/machines/portal_3x" "$machine"
sed -i 's/^kenngr.swe_pos .*/kenngr.swe_pos 20000000/; s/^kenngr.swe_neg .*/kenngr.swe_neg -20000000/' \
  "$machine"/x.lis "$machine"/y.lis "$machine"/z.lis

# --- 3. the full check and rs274, in turn on one core -----------------------------------------
# timed NAME CMD...: one run on $CORE; sets CPU_S (user + system) and RSS_KB, RC.
timed() {
  local log="$WORK/time-full-$1.log" name="$1"
  shift
  set +e
  taskset -c "$CORE" /usr/bin/time -v -o "$log" "$@" >"$WORK/full-$name.stdout" \
    2>"$WORK/full-$name.stderr"
  RC=$?
  set -e
  CPU_S="$(awk -F': ' '/User time \(seconds\)|System time \(seconds\)/ { s += $2 }
    END { printf "%.3f", s }' "$log")"
  RSS_KB="$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$log")"
}
smaller() { [[ -z "$1" ]] || awk -v a="$2" -v b="$1" 'BEGIN { exit !(a < b) }'; }

say "ncsim check --machine portal_3x_wide and rs274 -g, in turn ($RUNS runs each, core $CORE)"
NC_S="" NC_RSS_KB=0 RS_S="" RS_RSS_KB=0
for ((i = 1; i <= RUNS; i++)); do
  timed ncsim "$NCSIM" check --machine "$machine" "$WORK/bench.nc"
  if [[ "$RC" != 0 ]]; then
    head -n 20 "$WORK/full-ncsim.stderr" >&2 || true
    die "ncsim check exited $RC: the program is not accepted on $machine"
  fi
  if smaller "$NC_S" "$CPU_S"; then NC_S="$CPU_S"; fi
  if ((RSS_KB > NC_RSS_KB)); then NC_RSS_KB="$RSS_KB"; fi
  timed rs274 "$RS274" -g -t "$WORK/tool.tbl" "$WORK/bench.ngc" "$WORK/full-rs274.out"
  if [[ "$RC" != 0 ]] || ! grep -q 'PROGRAM_END()' "$WORK/full-rs274.out"; then
    die "rs274 did not reach the program end (exit $RC): the .ngc program is not accepted"
  fi
  if smaller "$RS_S" "$CPU_S"; then RS_S="$CPU_S"; fi
  if ((RSS_KB > RS_RSS_KB)); then RS_RSS_KB="$RSS_KB"; fi
done

# --- 4. table ---------------------------------------------------------------------------------
awk -v n="$BLOCKS" -v rs="$RS_S" -v rsm="$RS_RSS_KB" -v nc="$NC_S" -v ncm="$NC_RSS_KB" \
  -v strict="${STRICT:-0}" -v load="$(cut -d' ' -f1-3 /proc/loadavg)" '
  function rate(t) { return t > 0 ? n / t : 0 }
  BEGIN {
    r_rs = rate(rs); r_nc = rate(nc); ratio = r_rs > 0 ? r_nc / r_rs : 0
    printf "\n%-26s %10s %9s %12s %14s\n", "full check, 1 core", "blocks", "CPU [s]", "blocks/s",
      "peak RSS [MB]"
    printf "%-26s %10d %9.3f %12.0f %14.1f\n", "ncsim check --machine", n, nc, r_nc, ncm / 1024
    printf "%-26s %10d %9.3f %12.0f %14.1f\n", "linuxcnc rs274 -g", n, rs, r_rs, rsm / 1024
    printf "%-26s %10s %9s %11.1fx\n", "ratio ncsim / rs274", "", "", ratio
    printf "(blocks/s from the least CPU time, user + system, of the runs; load %s)\n\n", load
    ok = ratio >= 10
    printf "target ncsim full check >= 10x rs274 : %s\n", ok ? "met" : "MISSED"
    exit (strict && !ok) ? 1 : 0
  }'
