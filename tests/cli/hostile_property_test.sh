#!/usr/bin/env bash
# hostile_property_test.sh NCSIM ROOT [CASES] [SEED]: issue 34's property over seeded hostile
# inputs, on machines/portal_3x_override (overrides up to 1000 %).
# Each case is a random program mixing ordinary moves with extreme values (radii from 1e-3 to
# 1e12 mm, feeds from 1e-3 to 1e9 mm/min, zero-length and 1e-6 mm moves, dwells up to 1e7 s,
# G93 block times, open spline sections, loops) and a random scenario (overrides 0, 1e-300,
# 0.05 .. 300 %, feed holds). For `time --json` and `run -o`, bounded by --max-time 20:
#   - the command ends (no hang: a 60 s wall-clock guard) with a status ncsim documents
#     (0 ok, 1 program error, 2 usage or configuration, 3 audit);
#   - `time --json` writes JSON that parses (node's JSON.parse), one object;
#   - no NaN or infinity reaches stdout, stderr or the CSV;
#   - `run -o` leaves no temporary file beside its target.
# Deterministic: awk's srand(seed) per case.
set -uo pipefail
ncsim=$1
machine=$2/machines/portal_3x_override
cases=${3:-40}
seed0=${4:-34}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0

fail() {
  failures=$((failures + 1))
  echo "FAIL case $1: $2"
}

# program SEED > FILE
program() {
  awk -v seed="$1" '
  function pow10(lo, hi) { return 10 ^ (lo + int(rand() * (hi - lo + 1))) }
  BEGIN {
    srand(seed)
    print "%hostile" seed
    print "G17 G90 G71 G94"
    print "G00 X100 Y100 Z0"
    x = 100; y = 100
    n = 4 + int(rand() * 8)
    for (i = 0; i < n; ++i) {
      r = rand()
      if (r < 0.2) {
        x = 50 + int(rand() * 500) / 5; y = 50 + int(rand() * 500) / 5
        printf "G01 X%.3f Y%.3f F%.6g\n", x, y, pow10(-3, 9)
      } else if (r < 0.35) {
        R = pow10(-3, 12)
        printf "G02 X%.3f Y%.3f I%.6f J-%.0f F%d\n", x + 10, y, 5, R, 1000
        x = x + 10
      } else if (r < 0.45) {
        printf "G01 X%.3f F6000\n", x
      } else if (r < 0.55) {
        printf "G01 X%.7f F600\n", x + 0.000001; x = x + 0.000001
      } else if (r < 0.65) {
        printf "G04 %.6g\n", pow10(-3, 7)
      } else if (r < 0.72) {
        printf "G93 G01 X%.3f F%.6g\nG94\n", x + 1, pow10(-3, 9); x = x + 1
        print "F3000"
      } else if (r < 0.82) {
        print "#SPLINE ON"
        for (k = 0; k < 1 + int(rand() * 4); ++k) {
          x = x + 5; y = y + (rand() < 0.5 ? 3 : -3)
          printf "G01 X%.3f Y%.3f F2000\n", x, y
        }
        if (rand() < 0.5) print "#SPLINE OFF"
      } else if (r < 0.9) {
        print "P1 = 0"
        print "$WHILE P1 < 3"
        printf "G01 X%.3f F4000\n", x
        print "P1 = P1 + 1"
        print "$ENDWHILE"
      } else {
        printf "G00 X%.3f Y%.3f\n", 100 + rand() * 50, 100 + rand() * 50
      }
    }
    print "M30"
  }' 
}

# scenario SEED > FILE: override and feed-hold events at random times
scenario() {
  awk -v seed="$1" '
  BEGIN {
    srand(seed + 7919)
    split("0 1e-300 0.05 5 50 100 150 300", ov, " ")
    print "description = \"hostile property case\""
    n = int(rand() * 4)
    t = 0
    for (i = 0; i < n; ++i) {
      t = t + int(rand() * 30) / 10
      print "[[event]]"
      printf "at = %.1f\n", t
      if (rand() < 0.7) {
        printf "override = %s\n", ov[1 + int(rand() * 8)]
      } else {
        printf "feed_hold = %s\n", rand() < 0.5 ? "true" : "false"
      }
    }
  }'
}

documented() { [[ $1 -eq 0 || $1 -eq 1 || $1 -eq 2 || $1 -eq 3 ]]; }
no_nan() { ! grep -Eiq '(^|[^a-z_])-?(nan|inf)([^a-z_]|$)' "$@"; }

for ((c = 0; c < cases; ++c)); do
  seed=$((seed0 * 1000 + c))
  dir="$work/c$c"
  mkdir -p "$dir"
  program "$seed" >"$dir/p.nc"
  scenario "$seed" >"$dir/s.toml"
  # time --json
  timeout 60 "$ncsim" time --json --max-time 20 --machine "$machine" --scenario "$dir/s.toml" "$dir/p.nc" \
    >"$dir/t.out" 2>"$dir/t.err" </dev/null
  st=$?
  checks=$((checks + 1))
  if ! documented "$st"; then
    fail "$c" "time exit $st (seed $seed)"
    sed 's/^/  /' "$dir/t.err" | head -5
    continue
  fi
  if [[ $st -eq 0 || -s $dir/t.out ]]; then
    if ! node -e 'JSON.parse(require("fs").readFileSync(0, "utf8"))' <"$dir/t.out" 2>/dev/null; then
      fail "$c" "time --json is no JSON (seed $seed)"
      head -c 300 "$dir/t.out"
      echo
    fi
  fi
  if ! no_nan "$dir/t.out" "$dir/t.err"; then fail "$c" "NaN or inf in time's output (seed $seed)"; fi
  # run -o
  timeout 60 "$ncsim" run --max-time 20 --machine "$machine" --scenario "$dir/s.toml" -o "$dir/out.csv" "$dir/p.nc" \
    >"$dir/r.out" 2>"$dir/r.err" </dev/null
  st=$?
  checks=$((checks + 1))
  if ! documented "$st"; then fail "$c" "run exit $st (seed $seed)"; fi
  if compgen -G "$dir/out.csv.*" >/dev/null || compgen -G "$dir/*.tmp" >/dev/null; then
    fail "$c" "run left a temporary file: $(ls "$dir")"
  fi
  if [[ -f $dir/out.csv ]] && ! no_nan "$dir/out.csv" "$dir/r.err"; then
    fail "$c" "NaN or inf in the CSV or on stderr (seed $seed)"
  fi
done
ok=$(grep -l '"status"' "$work"/c*/t.out 2>/dev/null | wc -l)
echo "hostile_property_test: $cases cases, $checks runs ($ok with a JSON result), $failures failures"
((failures == 0))
