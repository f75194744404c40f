#!/usr/bin/env bash
# channel_keys_test.sh NCSIM FIXTURES: channel-list keys the planner and the interpolator read,
# end to end on copies of portal_3x's lists (issue 12, acceptance review F3, F4, F6).
set -uo pipefail
ncsim=$1
fixtures=$2
root=$(cd "$fixtures/../.." && pwd)

# expect, holds, summary: tests/cli/expect.sh.
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"

# machine_with NAME LINE: portal_3x in $work/NAME with LINE as the channel list's last line.
machine_with() {
  local dir=$work/$1
  cp -r "$root/machines/portal_3x" "$dir"
  printf '%s\n' "$2" >>"$dir/channel.lis"
  echo "$dir"
}

# first_v CSV LINE: v_path of the first row of the block at file line LINE (run --detail).
first_v() {
  grep -v '^#' "$1" | awk -F, -v want="$2" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    $col["line"] == want { print $col["v_path"]; exit }'
}
# near VALUE WANT TOL: |VALUE - WANT| <= TOL.
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; exit !(a != "" && d <= t && d >= -t) }'; }

# ---- P-CHAN-00009 corr_v_trans_jerk (isg-language.md §7.1) -----------------------------------
# A line into a tangent arc of R 1 mm under TRAPEZ (portal_3x: Y's J = 50000 mm/s^3, T = 1 ms):
# with the C1 rule the link is sqrt(J T R) = 7.0711 mm/s; without it the arc's own cap, 29.24.
printf '%%c1\nN1 #SLOPE [TYPE=TRAPEZ]\nN10 G00 X50 Y100\nN20 G01 X100 F6000\nN30 G03 X100 Y102 I0 J1\nN40 G01 X50\nN50 M30\n' \
  >"$work/c1_tan.nc"
for v in 0 1; do
  expect "P-CHAN-00009 $v: the list loads and the program runs" 0 '' '' -- \
    run --detail -o "$work/c1_$v.csv" --machine "$(machine_with c1_$v "corr_v_trans_jerk $v")" \
    "$work/c1_tan.nc"
done
"$ncsim" run --detail -o "$work/c1_none.csv" "$work/c1_tan.nc" 2>/dev/null
v0=$(first_v "$work/c1_0.csv" 5)
v1=$(first_v "$work/c1_1.csv" 5)
vn=$(first_v "$work/c1_none.csv" 5)
holds "P-CHAN-00009 1: the arc starts at the C1 link sqrt(J T R) = 7.0711 mm/s (got $v1)" near "$v1" 7.0711 0.001
holds "P-CHAN-00009 0: the arc starts at its own cap, 29.24 mm/s (got $v0)" near "$v0" 29.24 0.01
holds "P-CHAN-00009 absent: ncsim's default 1, the C1 link (got $vn)" near "$vn" 7.0711 0.001
expect "P-CHAN-00009 1: the audit passes the C1 step at j T" 0 \
  'C1 steps 2, closest to j T: .* \|da\| 50 of 50 mm/s\^2 at the link velocity 7\.07107 mm/s' '' -- \
  time --audit --machine "$work/c1_1" "$work/c1_tan.nc"
expect "P-CHAN-00009 0: the audit does not bound the step the manual allows (exit 0)" 0 \
  '^audit: ok$' '' -- time --audit --machine "$work/c1_0" "$work/c1_tan.nc"
expect "P-CHAN-00009 2 is not a BOOLEAN: NC3004 at its line, exit 2" 2 '' \
  'c1_2/channel\.lis:3:[0-9]+: error: corr_v_trans_jerk \(P-CHAN-00009\) = 2 is outside its range 0\.\.1 \[NC3004\]' -- \
  time --machine "$(machine_with c1_2 "corr_v_trans_jerk 2")" "$work/c1_tan.nc"

# ---- NCSIM-CHAN-620 ncsim.default_path_dev: G261's radius without PATH_DEV -------------------
# A 90 degree corner under G261 without #CONTOUR MODE: the blend's deviation from the corner is
# its radius (docs/planner.md "Tolerance balls"), the audit's tolerance the radius.
printf '%%ball\nN10 G01 X100 F6000\nN20 G261 Y100\nN30 X0\nN40 M30\n' >"$work/ball.nc"
expect "NCSIM-CHAN-620 absent: the manual's PATH_DEV 1 mm" 0 \
  'contour deviation 0\.9[0-9]* mm \(tolerance 1 mm\)' '' -- time --audit "$work/ball.nc"
expect "NCSIM-CHAN-620 0.5: a ball of 0.5 mm" 0 \
  'contour deviation 0\.4[0-9]* mm \(tolerance 0\.5 mm\)' '' -- \
  time --audit --machine "$(machine_with dev_05 "ncsim.default_path_dev 0.5")" "$work/ball.nc"
t05=$("$ncsim" time --machine "$work/dev_05" "$work/ball.nc" 2>/dev/null | cut -d' ' -f2)
t10=$("$ncsim" time "$work/ball.nc" 2>/dev/null | cut -d' ' -f2)
holds "NCSIM-CHAN-620: the radius changes the machining time ($t05 s with 0.5 mm, $t10 s with 1 mm)" \
  test -n "$t05" -a -n "$t10" -a "$t05" != "$t10"
# A 45 degree turn: a 0.2 mm ball at the right angle above is passed more slowly than its
# VELOJUMP corner, which G261 then keeps (deviation 0; docs/planner.md "Tolerance balls").
printf '%%ball\nN5 #CONTOUR MODE [DEV, PATH_DEV=0.2]\nN10 G01 X100 F6000\nN20 G261 X150 Y50\nN30 X200\nN40 M30\n' \
  >"$work/ball_02.nc"
expect "NCSIM-CHAN-620 0.5: #CONTOUR MODE PATH_DEV=0.2 replaces it" 0 \
  'contour deviation 0\.1[0-9]* mm \(tolerance 0\.2 mm\)' '' -- \
  time --audit --machine "$work/dev_05" "$work/ball_02.nc"
expect "NCSIM-CHAN-620 0 is below its range: NC3004 at its line, exit 2" 2 '' \
  'dev_0/channel\.lis:3:[0-9]+: error: ncsim\.default_path_dev \(NCSIM-CHAN-620\) = 0 is outside its range' -- \
  time --machine "$(machine_with dev_0 "ncsim.default_path_dev 0")" "$work/ball.nc"
# The axis list's nci.tolerance_ball (NCSIM-AXIS-021), never read, is retired and names the key.
dir=$(machine_with ball_axis "")
printf 'nci.tolerance_ball 0.5\n' >>"$dir/x.lis"
expect "nci.tolerance_ball in an axis list: NC3015 naming ncsim.default_path_dev" 2 '' \
  'x\.lis:[0-9]+:[0-9]+: error: nci\.tolerance_ball is no longer read .*ncsim\.default_path_dev \(NCSIM-CHAN-620\).* \[NC3015\]' -- \
  time --machine "$dir" "$work/ball.nc"

summary channel_keys_test
