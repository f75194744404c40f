#!/usr/bin/env bash
# random_scenarios.sh NCSIM ROOT [CASES] [SEED]: seeded random override / feed-hold scenarios
# over seeded random programs (lines, arcs, blends, dwells) on portal_3x under each path
# override type (issue 13, docs/scenario.md). Per case:
#   - `time --audit` exits 0 with `audit: ok` (every axis limit and the contour tolerance kept);
#   - `time --json` says status ok and stop "program end" (the program completes);
#   - `time`'s total equals `run`'s last t, and run's last row is the program's end point;
#   - two `run`s write byte-identical CSVs.
# Deterministic: awk's srand(seed) per case (the same awk gives the same programs).
set -uo pipefail
ncsim=$1
root=$2
cases=${3:-12}
seed0=${4:-13}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

types=(REDUCED ORIGINAL REDUCED_ABOVE_100)
for t in "${types[@]}"; do
  mkdir -p "$work/m_$t"
  cp "$root/machines/portal_3x/"* "$work/m_$t/"
  printf '\nncsim.path_override_type %s\n' "$t" >>"$work/m_$t/channel.lis"
done

# program SEED > FILE: a random program; its last line is a comment with the end point.
program() {
  awk -v seed="$1" '
  function line_move() {
    x = 20 + int(rand() * 1400) / 10; y = 20 + int(rand() * 1400) / 10
    nz = int(rand() * 3) == 0 ? int(rand() * 100) / 10 : z
    if (rand() < 0.3) f = 1200 + int(rand() * 6) * 900
    printf "G01 X%.3f Y%.3f Z%.3f F%d\n", x, y, nz, f; z = nz
  }
  BEGIN {
    srand(seed); pi = 3.14159265358979
    x = 60; y = 60; z = 0
    print "%rand" seed
    print "N10 G17 G90 G71 G94"
    print "G00 X60 Y60 Z0"
    if (rand() < 0.6) {
      printf "#CONTOUR MODE [DEV PATH_DEV=%g]\nG261\n", 0.2 + int(rand() * 5) * 0.2
    }
    f = 1200 + int(rand() * 6) * 900
    printf "G01 X%.3f Y60 F%d\n", x + 5, f; x += 5
    n = 6 + int(rand() * 8)
    for (i = 0; i < n; ++i) {
      r = rand()
      if (r < 0.45) {
        line_move()
      } else if (r < 0.9) {
        R = 5 + int(rand() * 250) / 10
        a0 = rand() * 2 * pi
        cx = x - R * cos(a0); cy = y - R * sin(a0)
        d = (30 + rand() * 270) * pi / 180
        dir = rand() < 0.5 ? 2 : 3
        a1 = dir == 3 ? a0 + d : a0 - d
        ex = cx + R * cos(a1); ey = cy + R * sin(a1)
        if (cx - R < 5 || cx + R > 195 || cy - R < 5 || cy + R > 195) { line_move(); continue }
        ex = sprintf("%.6f", ex) + 0; ey = sprintf("%.6f", ey) + 0
        printf "G0%d X%.6f Y%.6f I%.6f J%.6f\n", dir, ex, ey, cx - x, cy - y
        x = ex; y = ey
      } else {
        printf "G04 X%.2f\n", 0.01 + int(rand() * 10) / 100
      }
    }
    print "M30"
    printf "; end %.6f %.6f %.6f\n", x, y, z
  }'
}

# scenario SEED T TYPE LINE: random events within the run's plain time T [s]; LINE: a motion
# line for a line event.
scenario() {
  awk -v seed="$1" -v T="$2" -v type="$3" -v line="$4" 'BEGIN {
    srand(seed)
    top = type == "REDUCED_ABOVE_100" ? 150 : 100
    n = 2 + int(rand() * 6); t = 0
    for (i = 0; i < n; ++i) {
      t += rand() * T / n
      printf "[[event]]\nat = %.4f\n", t
      r = rand()
      if (r < 0.35) printf "feed_hold = true\nduration = %.3f\n", 0.02 + rand() * 0.4
      else if (r < 0.5) print "override = 0"
      else printf "override = %d\n", 5 + int(rand() * (top - 5))
    }
    # The last change lets the program end: an override > 0 (holds release by duration).
    printf "[[event]]\nat = %.4f\noverride = %d\n", t + 0.01, 20 + int(rand() * (top - 20))
    if (rand() < 0.5) printf "[[event]]\nline = %d\noverride = %d\n", line, 10 + int(rand() * 90)
  }'
}

field() { sed -E "s/.*\"$1\":(\"[^\"]*\"|[^,}]*).*/\\1/" "$2"; }

for ((c = 0; c < cases; ++c)); do
  s=$((seed0 * 1000 + c))
  type=${types[$((c % 3))]}
  m="$work/m_$type"
  p="$work/r$c.nc"
  program "$s" >"$p"
  plain=$("$ncsim" time --json --machine "$m" "$p" 2>"$work/err")
  if [[ $(field status <(echo "$plain")) != '"ok"' ]]; then
    echo "FAIL case $c (seed $s): the program itself fails"; cat "$p" "$work/err"
    failures=$((failures + 1)); continue
  fi
  t0=$(field total_s <(echo "$plain"))
  sc="$work/r$c.toml"
  scenario "$((s + 1))" "$t0" "$type" "$(grep -n '^G0[123]' "$p" | sed -n 3p | cut -d: -f1)" >"$sc"
  why=""
  "$ncsim" time --audit --machine "$m" --scenario "$sc" "$p" >"$work/audit" 2>&1 ||
    why+=" time --audit exit $?;"
  grep -q '^audit: ok$' "$work/audit" || why+=" audit not ok;"
  "$ncsim" time --json --machine "$m" --scenario "$sc" "$p" >"$work/json" 2>&1
  [[ $(field status "$work/json") == '"ok"' ]] || why+=" status;"
  [[ $(field stop "$work/json") == '"program end"' ]] || why+=" stop $(field stop "$work/json");"
  total=$(field total_s "$work/json")
  "$ncsim" run --machine "$m" --scenario "$sc" -o "$work/a.csv" "$p" 2>/dev/null || why+=" run;"
  "$ncsim" run --machine "$m" --scenario "$sc" -o "$work/b.csv" "$p" 2>/dev/null
  cmp -s "$work/a.csv" "$work/b.csv" || why+=" reruns differ;"
  last=$(grep -v '^#' "$work/a.csv" | tail -1)
  [[ ${last%%,*} == "$total" ]] || why+=" time $total != run ${last%%,*};"
  read -r _ _ ex ey ez < <(tail -1 "$p")
  echo "$last" | awk -F, -v x="$ex" -v y="$ey" -v z="$ez" '
    function d(a, b) { return a > b ? a - b : b - a }
    { exit !(d($3, x) < 1e-5 && d($4, y) < 1e-5 && d($5, z) < 1e-5) }' ||
    why+=" end point $last;"
  if [[ -n $why ]]; then
    failures=$((failures + 1))
    echo "FAIL case $c (seed $s, $type):$why"
    cat "$p" "$sc"
    head -20 "$work/audit"
  else
    echo "ok   case $c (seed $s, $type): $t0 s plain, $total s under $(grep -c '^\[\[event' "$sc") events"
  fi
done
echo "random scenarios: $((cases - failures)) passed, $failures failed"
((failures == 0))
