#!/usr/bin/env bash
# production_line_test.sh NCSIM: `ncsim line` end to end (docs/lines.md): the line file's
# positioned errors (exit 2), a #WAIT that can never be answered (exit 1, NC6401 naming both
# channels), a #WAIT on a channel a program run alone does not have (250008), the SYN timing.
set -uo pipefail
ncsim=$1
source "$(dirname "${BASH_SOURCE[0]}")/expect.sh"

cat >"$work/a.nc" <<'NC'
%a
G01 X100 F6000
#SIGNAL SYN [ID1 CH2]
M30
NC
cat >"$work/b.nc" <<'NC'
%b
#WAIT SYN [ID1 CH1]
G01 Y10 F6000
M30
NC
cat >"$work/line.toml" <<'TOML'
[[channel]]
number = 1
name = "cutter"
program = "a.nc"
machine = "portal_3x"
[[channel]]
number = 2
name = "picker"
program = "b.nc"
machine = "portal_3x"
TOML
expect "line time: channel 2 waits for channel 1's cut, to the cycle" 0 \
  '^  channel 2 picker: end 1\.[0-9]+ s, waiting 1\.[0-9]+ s, utilisation' '' \
  -- line time "$work/line.toml"

cat >"$work/bad.toml" <<'TOML'
cycle_us = 0
[[channel]]
number = 1
progam = "a.nc"
machine = "portal_3x"
TOML
expect "a bad line file: every error positioned, exit 2" 2 '' \
  'bad\.toml:1:12: error: .*\[NC7004\]' -- line time "$work/bad.toml"
again "... the unknown key with its suggestion" 2 '' \
  'bad\.toml:4:1: error: unknown key `channel\[1\]\.progam`; did you mean `program`\? \[NC7101\]'
again "... the missing program" 2 '' 'bad\.toml:2:1: error: .*no `program`.*\[NC7102\]'

cat >"$work/missing.toml" <<'TOML'
[[channel]]
number = 1
program = "nowhere.nc"
machine = "portal_3x"
TOML
expect "a program that does not exist: at its value, exit 2" 2 '' \
  'missing\.toml:3:11: error: no such program: .*\[NC7106\]' -- line time "$work/missing.toml"

cat >"$work/c.nc" <<'NC'
%c
G01 X5 F6000
#WAIT SYN [ID2 CH2]
M30
NC
cat >"$work/d.nc" <<'NC'
%d
#WAIT [ID1 CH1]
M30
NC
cat >"$work/dead.toml" <<'TOML'
[[channel]]
number = 1
program = "c.nc"
machine = "portal_3x"
[[channel]]
number = 2
program = "d.nc"
machine = "portal_3x"
TOML
expect "two channels waiting for each other: NC6401 naming both, exit 1" 1 '' \
  'c\.nc:3:1: error: run-time error at t=[0-9.]+ s: channel 1 waits at line 3 for signal 2 of channel 2, which can never come: channel 2 waits itself at line 2 for signal 1 of channel 1 \[NC6401\]' \
  -- line time "$work/dead.toml"
again "... and the other channel's error too" 1 '' 'd\.nc:2:1: error: .*channel 2 waits at line 2.*\[NC6401\]'

expect "a program alone waiting for itself: NC6401, never a hang" 1 '' \
  'b\.nc:2:1: error: run-time error at t=[0-9.]+ s: channel 1 waits at line 2 for signal 1 of channel 1, which can never come.*\[NC6401\]' \
  -- time "$work/b.nc"
expect "a program alone: #SIGNAL SYN to channel 2 is 250008 at its CH" 1 '' \
  'a\.nc:3:18: error: #SIGNAL SYN names channel 2, which this run does not have \(its channels: 1\) \[250008\]' \
  -- time "$work/a.nc"
expect "check of one program accepts any channel 1 .. 12" 0 '' '' -- check "$work/a.nc"
expect "line check checks with the line's channels" 0 ': ok$' '' -- line check "$work/line.toml"
expect "line run needs -o" 2 '' 'needs -o DIR' -- line run "$work/line.toml"
summary "production lines"
