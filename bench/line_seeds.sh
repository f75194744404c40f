#!/usr/bin/env bash
# bench/line_seeds.sh [N] [FIRST]: programs/lines/two_pickers over N seeded random streams
# (seeds FIRST .. FIRST+N-1, default 200 from 1; docs/lines.md "Workpieces along the belt"):
# each run's `ncsim line time --json` must close its counts (taken + missed = arrived, nothing
# on the belt, every channel at its program end); prints the totals, the spread of the
# workpieces per minute and the CPU time. Exit 1 at the first run that does not close.
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
NCSIM="${NCSIM_BUILD_DIR:-$REPO/build/release}/cli/ncsim"
N=${1:-200}
FIRST=${2:-1}
SRC="$REPO/programs/lines/two_pickers"
WORK=$(mktemp -d /tmp/ncsim-line-seeds.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
start=$(date +%s.%N)
for ((seed = FIRST; seed < FIRST + N; ++seed)); do
  sed -E -e "s/^seed = [0-9]+/seed = $seed/" -e "s#^(program|machine) = \"#\1 = \"$SRC/#" \
    "$SRC/line.toml" >"$WORK/line.toml"
  "$NCSIM" line time --json "$WORK/line.toml" >"$WORK/$seed.json" 2>"$WORK/$seed.err" || {
    echo "seed $seed: exit $? ($(head -1 "$WORK/$seed.err"))"
    exit 1
  }
done
end=$(date +%s.%N)
python3 - "$WORK" "$FIRST" "$N" "$start" "$end" <<'PY'
import json, sys
work, first, n, t0, t1 = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
arrived = taken = missed = 0
rates, per_channel = [], {}
for seed in range(first, first + n):
    r = json.load(open(f"{work}/{seed}.json"))
    w = r["workpieces"]
    if w["taken"] + w["missed"] != w["arrived"] or w["on_belt"] != 0:
        sys.exit(f"seed {seed}: {w['arrived']} arrived, {w['taken']} taken, {w['missed']} missed, {w['on_belt']} on the belt")
    for c in r["channels"]:
        if c["stop"] != "program end":
            sys.exit(f"seed {seed}: channel {c['number']} ended by {c['stop']}: {c.get('error', '')}")
        per_channel[c["name"]] = per_channel.get(c["name"], 0) + c["taken"]
    arrived += w["arrived"]; taken += w["taken"]; missed += w["missed"]
    rates.append(w["per_minute"])
rates.sort()
print(f"line_seeds: {n} seeds, {arrived} arrived = {taken} taken + {missed} missed; taken per channel {per_channel}")
print(f"  workpieces per minute: min {rates[0]:.1f}, median {rates[len(rates)//2]:.1f}, max {rates[-1]:.1f}; {t1 - t0:.1f} s wall for {n} runs")
PY
