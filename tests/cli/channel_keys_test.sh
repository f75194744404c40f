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
expect "P-CHAN-00009 2 is not a BOOLEAN: NC3004 at its line, exit 2" 2 '' \
  'c1_2/channel\.lis:3:[0-9]+: error: corr_v_trans_jerk \(P-CHAN-00009\) = 2 is outside its range 0\.\.1 \[NC3004\]' -- \
  time --machine "$(machine_with c1_2 "corr_v_trans_jerk 2")" "$work/c1_tan.nc"

summary channel_keys_test
