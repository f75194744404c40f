#!/usr/bin/env bash
# bench/line_cost.sh [NCSIM]: what a second channel costs (issue 37: "two channels cost less
# than twice one"). CPU time of `ncsim line time` on programs/lines/two_pickers (two delta
# pickers on one belt) against the same line file with only its channel 1 and only its
# channel 2 (each alone on the same belt and stream: it takes what it can, the rest is
# missed). Prints the three CPU times (bench/cpu.py: least and median of RUNS, default 3) and
# the ratio two / the mean of the two alone; exit 1 when that ratio is 2 or more.
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
NCSIM="${1:-${NCSIM_BUILD_DIR:-$REPO/build/release}/cli/ncsim}"
RUNS="${RUNS:-3}"
SRC="$REPO/programs/lines/two_pickers"
WORK=$(mktemp -d /tmp/ncsim-line-cost.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
# The line file with absolute program and machine paths, then with one [[channel]] table
# removed (tables start at "[[channel]]" and end at the next table).
sed -E "s#^(program|machine) = \"#\1 = \"$SRC/#" "$SRC/line.toml" >"$WORK/both.toml"
only() {  # only N: the line file without the channel tables whose number is not N
  awk -v keep="$1" '
    /^\[\[channel\]\]/ { if (buf != "") { if (num == keep) printf "%s", buf }; buf = $0 "\n"; inch = 1; num = ""; next }
    /^\[/ && inch { if (num == keep) printf "%s", buf; buf = ""; inch = 0 }
    inch { buf = buf $0 "\n"; if ($1 == "number") num = $3; next }
    { print }
    END { if (inch && num == keep) printf "%s", buf }' "$WORK/both.toml"
}
only 1 >"$WORK/one.toml"
only 2 >"$WORK/two_alone.toml"
cpu() {  # cpu LABEL FILE: prints bench/cpu.py's line, returns the median CPU [s] in $median
  local line
  line=$(python3 "$REPO/bench/cpu.py" --runs "$RUNS" --label "$1" -- "$NCSIM" line time "$2")
  echo "$line"
  median=$(sed -E 's@.*CPU [0-9.]+ / ([0-9.]+) s.*@\1@' <<<"$line")
}
cpu "line time, channel 1 alone" "$WORK/one.toml"
m1=$median
cpu "line time, channel 2 alone" "$WORK/two_alone.toml"
m2=$median
cpu "line time, both channels" "$WORK/both.toml"
m12=$median
python3 - "$m1" "$m2" "$m12" <<'PY'
import sys
one, two, both = (float(x) for x in sys.argv[1:])
ratio = both / ((one + two) / 2)
print(f"line_cost: both {both:.3f} s, alone {one:.3f} / {two:.3f} s: {ratio:.2f}x one channel "
      f"(target < 2x: {'met' if ratio < 2 else 'MISSED'})")
sys.exit(0 if ratio < 2 else 1)
PY
