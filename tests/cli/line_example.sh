#!/usr/bin/env bash
# line_example.sh NCSIM LINE_FOLDER: a bundled production line (programs/lines/<name>/,
# docs/lines.md) checks clean, runs to its end with every channel's time, writes one CSV per
# channel and reruns byte-identically.
set -uo pipefail
ncsim=$1
folder=$2
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"
line=$folder/line.toml

expect "line check: every channel's program checks with the line's channels" 0 ': ok$' '' \
  -- line check "$line"
expect "line time: the line's end and one row per channel, no error" 0 \
  '^  channel 2 [^:]*: end [0-9.]+ s, waiting [0-9.]+ s, utilisation [0-9.]+ %, program end(, took [0-9]+ \(sensor at [0-9.]+ mm\))?$' \
  '' -- line time "$line"
cp "$work/out" "$work/time1"
# Nothing lost (docs/lines.md "Workpieces along the belt"): arrived = taken + missed + on the belt.
if grep -q '^  belt: ' "$work/time1"; then
  holds "belt: arrived = taken + missed + on the belt" bash -c "
    read -r a t m b < <(sed -nE 's/^  belt: ([0-9]+) workpieces? arrived, ([0-9]+) taken .*\), ([0-9]+) missed, ([0-9]+) on the belt.*/\1 \2 \3 \4/p' '$work/time1')
    [[ -n \$a ]] && (( a == t + m + b ))"
  holds "belt: one fate line per workpiece" bash -c "
    a=\$(sed -nE 's/^  belt: ([0-9]+) workpiece.*/\1/p' '$work/time1')
    [[ \$(grep -c '^  workpiece [0-9]*: arrived' '$work/time1') -eq \$a ]]"
fi
expect "line time --json: one JSON object" 0 '^\{"line":' '' -- line time --json "$line"
holds "line time --json: the channels and, with a belt, counts that close" python3 -c "
import json, sys
r = json.load(open('$work/out'))
assert len(r['channels']) >= 2 and r['end_s'] > 0
w = r.get('workpieces')
if w is not None:
    assert w['taken'] + w['missed'] + w['on_belt'] == w['arrived'], w
    assert len(w['fates']) == w['arrived']
    assert sum(c.get('taken', 0) for c in r['channels']) == w['taken']
"
expect "line time --audit: every channel's setpoints within their limits" 0 '' '' \
  -- line time --audit "$line"
mkdir -p "$work/a" "$work/b"
expect "line run -o DIR: one CSV per channel" 0 '' '' -- line run "$line" -o "$work/a"
holds "two CSVs, each closed by its stop" \
  bash -c "[[ \$(ls '$work/a' | wc -l) -ge 2 ]] && grep -q '^# stop: program end$' '$work/a'/ch1_*.csv"
"$ncsim" line run "$line" -o "$work/b" >/dev/null 2>&1
for f in "$work/a"/*.csv; do
  same "rerun byte-identical: $(basename "$f")" "$f" "$work/b/$(basename "$f")"
done
"$ncsim" line time "$line" >"$work/time2" 2>/dev/null
same "line time reruns byte-identically" "$work/time1" "$work/time2"
summary "line $(basename "$folder")"
