#!/usr/bin/env bash
# golden_cli_test.sh NCSIM: end-to-end checks of `ncsim golden check` and `ncsim golden bless`
# (docs/golden.md) on a small program library made in a temporary folder.
set -uo pipefail
ncsim=$1

# expect, same: shared with tests/cli/cli_test.sh.
source "$(dirname "${BASH_SOURCE[0]}")/../cli/expect.sh"

lib=$work/programs
mkdir -p "$lib/square" "$lib/stops" "$lib/empty"
cat >"$lib/square/square.nc" <<'NC'
%square
N10 G90 G01 X0 Y0 Z5 F3000
N20 X40
N30 Y30
N40 X0
N50 Y0
N60 M30
NC
echo portal_3x >"$lib/square/machine"
cat >"$lib/stops/stops.nc" <<'NC'
%stops
N10 G90 G01 X10 Y0 Z5 F3000
N20 G92 X0
N30 X20
N40 M30
NC
echo portal_3x >"$lib/stops/machine"
g=$lib/square/square.golden

expect "check without a golden fails and says how to bless" 1 'NO GOLDEN' \
  'square\.golden: error: no golden .*ncsim golden bless .*\[NC8005\]' -- golden check "$lib/square"
[[ ! -e $g ]] && echo "ok   check wrote no golden" || { failures=$((failures + 1)); echo "FAIL check wrote a golden"; }
checks=$((checks + 1))
expect "bless needs programs or --all" 2 '' 'PROGRAM\.\.\. or --all' -- golden bless
expect "bless takes programs or --all, not both" 2 '' '' -- golden bless --all "$lib/square"
expect "a folder without its program is a usage error" 2 '' '\[NC8008\]' -- golden check "$lib/empty"
expect "a missing program is a usage error" 2 '' '\[NC8008\]' -- golden check "$work/none"
expect "bless writes a new golden" 0 'square: blessed, new \(.*status 0\)' '' -- \
  golden bless "$lib/square"
cp "$g" "$work/first.golden"
expect "the run matches its golden" 0 'square: ok \(' '' -- golden check "$lib/square"
expect "the program file names its golden too" 0 'ok' '' -- golden check "$lib/square/square.nc"
expect "a second bless is unchanged" 0 'blessed, unchanged' '' -- golden bless "$lib/square"
same "blessing again gives the same bytes" "$work/first.golden" "$g"
(cd "$lib" && "$ncsim" golden bless square >/dev/null 2>&1)
same "the golden does not depend on the working folder" "$work/first.golden" "$g"
checks=$((checks + 1))
if grep -q '^program square.nc$' "$g" && grep -q '^end t=[0-9.]* cycles=[0-9]* status=0$' "$g" &&
  grep -q '^b ' "$g" && grep -q '^s ' "$g"; then
  echo "ok   the golden holds the program name, samples, block ends and the end"
else
  failures=$((failures + 1)); echo "FAIL golden content"; cat "$g"
fi

# A moved position: the first sample row's X, 0.5 mm off.
awk 'BEGIN{done=0} /^s / && !done {$4 = $4 + 0.5; done=1} {print}' "$work/first.golden" >"$g"
cp "$g" "$work/moved.golden"
expect "a moved position fails with time, line, axis, size and tolerance" 1 \
  'square: MISMATCH, 1 deviation, the first at t=[0-9.]+ s line [0-9]+ axis X' \
  'square\.golden:[0-9]+: error: square\.nc t=[0-9.]+ s line [0-9]+: X is .* off by 0\.5 \(tolerance 0\.0001\) \[NC8001\]' \
  -- golden check "$lib/square"
same "check never rewrites a golden" "$work/moved.golden" "$g"
# A tolerance of the golden's own is kept by bless and used by check.
sed -i 's/^tolerance X=0.0001/tolerance X=1/' "$g"
expect "a wider stated tolerance accepts the moved position" 0 'ok' '' -- golden check "$lib/square"
expect "bless keeps the golden's tolerances" 0 'blessed, changed' '' -- golden bless "$lib/square"
checks=$((checks + 1))
if grep -q '^tolerance X=1 Y=0.0001 Z=0.0001$' "$g"; then echo "ok   tolerance kept"; else
  failures=$((failures + 1)); echo "FAIL tolerance kept"; grep '^tolerance' "$g"; fi
cp "$work/first.golden" "$g"

# A block end moved by two cycles and a shorter run.
awk '/^b / && !done {split($2, t, "."); $2 = $2 + 0.002; done=1} {print}' "$work/first.golden" >"$g"
expect "a block end two cycles off fails" 1 '' 'block line [0-9]+ ends at .* 2 cycles apart .*\[NC8002\]' \
  -- golden check "$lib/square"
cp "$work/first.golden" "$g"
sed -i 's/^end t=\([0-9.]*\) cycles=\([0-9]*\) status=0$/end t=\1 cycles=\2 status=1 error=NC6001 line=20/' "$g"
expect "another exit status fails as an end deviation" 1 '' 'ends with status 0, the golden with status 1 .*\[NC8003\]' \
  -- golden check "$lib/square"
printf 'golden 1\nprogram square.nc\nbogus 1\n' >"$g"
expect "a malformed golden names its line" 2 'FAILED' 'square\.golden:3: error: malformed golden: .*\[NC8006\]' \
  -- golden check "$lib/square"
cp "$work/first.golden" "$g"
# Issue 34 items 17 and 27: edits of a golden that used to pass or be placed wrongly.
grep -v '^s ' "$work/first.golden" >"$g"
expect "a golden with its sample rows deleted fails (NC8001)" 1 '' \
  'square\.golden:[0-9]+: error: .*the golden has no row at t=0\.05 s, a sample cycle .*\[NC8001\]' \
  -- golden check "$lib/square"
awk '/^s / && !done {$3 = $3 + 1000; done = 1} {print}' "$work/first.golden" >"$g"
expect "a sample row with a wrong line number fails (NC8002)" 1 '' \
  'in the golden, line [0-9]+ in the run .*\[NC8002\]' -- golden check "$lib/square"
: >"$g"
expect "an empty golden is named as such at line 1, not :0:" 2 'FAILED' \
  'square\.golden:1: error: malformed golden: the file is empty .*\[NC8006\]' -- golden check "$lib/square"
{ echo 'golden 1'; cat "$work/first.golden"; } >"$g"
expect "a repeated 'golden 1' record is refused at its line" 2 'FAILED' \
  "error: malformed golden: 'golden' given twice \\(first on line 1\\) \\[NC8006\\]" -- golden check "$lib/square"
cp "$work/first.golden" "$g"

# A program that stops with an error keeps the error as its golden.
expect "bless records a program's error" 0 'stops: blessed, new \(.*status 1, error NC6001 at line 3\)' '' \
  -- golden bless "$lib/stops"
checks=$((checks + 1))
if grep -Eq '^end t=[0-9.]+ cycles=[0-9]+ status=1 error=NC6001 line=3$' "$lib/stops/stops.golden" &&
  grep -q '^# stops.nc:3:' "$lib/stops/stops.golden"; then
  echo "ok   the error golden holds id, line and time"
else
  failures=$((failures + 1)); echo "FAIL error golden"; cat "$lib/stops/stops.golden"
fi
expect "the error program matches its golden" 0 'stops: ok' '' -- golden check "$lib/stops"

# The whole library.
rm -rf "$lib/empty"
expect "check with no program takes the whole library" 0 'golden: 2 programs, 2 ok' '' -- \
  golden check --programs "$lib"
expect "bless --all blesses the whole library" 0 'golden: 2 programs, 2 blessed' '' -- \
  golden bless --all --programs "$lib"
cp "$work/moved.golden" "$g"
expect "one mismatch fails the library check" 1 'golden: 2 programs, 1 ok, 1 mismatched' '' -- \
  golden check --programs "$lib"

# A line folder (docs/golden.md "Lines"): one golden per channel, checked and blessed together.
ln=$work/line
mkdir -p "$ln"
cat >"$ln/line.toml" <<'TOML'
[[channel]]
number = 1
name = "a"
program = "a.nc"
machine = "portal_3x"
[[channel]]
number = 2
name = "b"
program = "b.nc"
machine = "portal_3x"
TOML
printf '%%a\nN10 G90 G01 X30 Y0 Z5 F3000\nN20 #SIGNAL SYN [ID1 CH2]\nN30 M30\n' >"$ln/a.nc"
printf '%%b\nN10 #WAIT SYN [ID1 CH1]\nN20 G90 G01 X0 Y20 Z5 F3000\nN30 M30\n' >"$ln/b.nc"
expect "a line without goldens: one NO GOLDEN per channel" 1 'line/ch2_b: NO GOLDEN' \
  'ch1_a\.golden: error: no golden .*\[NC8005\]' -- golden check "$ln"
expect "bless a line writes one golden per channel" 0 'line/ch2_b: blessed, new' '' -- \
  golden bless "$ln"
holds "the channels' goldens are there" test -s "$ln/ch1_a.golden" -a -s "$ln/ch2_b.golden"
expect "the line matches its goldens" 0 'line/ch2_b: ok' '' -- golden check "$ln"
sed -i 's/X0 Y20/X0 Y25/' "$ln/b.nc"
expect "a channel that moves otherwise is a mismatch of its own golden" 1 \
  'line/ch2_b: MISMATCH, .* ncsim golden bless [^ ]*/line$' '' -- golden check "$ln"
holds "... and the other channel still matches" grep -q 'line/ch1_a: ok' "$work/out"

summary golden_cli
