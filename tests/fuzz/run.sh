#!/usr/bin/env bash
# tests/fuzz/run.sh SECONDS
#
# Builds the libFuzzer targets (clang, libFuzzer + ASan + UBSan, RelWithDebInfo) in build/fuzz
# and runs them one after the other, each for SECONDS:
#   1. fuzz_grammar over a copy of tests/fuzz/corpus/ plus tests/fuzz/regressions/;
#   2. fuzz_interp over a copy of tests/fuzz/corpus/, tests/fuzz/corpus_interp/,
#      programs/*/*.nc (prefixed with the byte that selects the program's machine, see
#      tests/fuzz/fuzz_interp.cpp) plus tests/fuzz/regressions/, with the NC words of
#      tests/fuzz/interp.dict as mutation dictionary.
# So a run takes 2 x SECONDS plus the build; CI calls it with 60, i.e. 2 minutes of fuzzing.
# The corpus copies and every artifact live in build/fuzz/, never in the repository.
# Exit status: 0 when both runs end without a crash, hang (> 10 s per input), leak,
# out-of-memory (> 2048 MB) or sanitizer report; non-zero otherwise, with the failing input
# left in build/fuzz/artifacts/ (grammar-crash-*, interp-timeout-*, ...). The interpreter
# target runs even when the grammar target failed.
set -euo pipefail

SECONDS_TO_RUN="${1:?usage: tests/fuzz/run.sh SECONDS}"
[[ "$SECONDS_TO_RUN" =~ ^[0-9]+$ ]] || { echo "run.sh: SECONDS must be an integer" >&2; exit 2; }
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="$REPO/build/fuzz"

cmake -S "$REPO" -B "$BUILD" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DNCSIM_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD" -j2 --target fuzz_grammar fuzz_interp

ARTIFACTS="$BUILD/artifacts"
mkdir -p "$ARTIFACTS"

# Inputs that once failed are replayed first, as part of each corpus.
copy_regressions() {  # copy_regressions DIR
  find "$REPO/tests/fuzz/regressions" -type f ! -name README.md -exec cp {} "$1"/ \;
}

# Byte that selects a program's machine in fuzz_interp (empty: portal_3x, no prefix).
machine_byte() {  # machine_byte NAME
  case "$1" in
    delta_picker) printf '\001' ;;
    laser_portal) printf '\002' ;;
    static_saw) printf '\003' ;;
    *) ;;
  esac
}

GRAMMAR_WORK="$BUILD/corpus-grammar"
rm -rf "$GRAMMAR_WORK" "$BUILD/corpus-work"
mkdir -p "$GRAMMAR_WORK"
cp "$REPO"/tests/fuzz/corpus/* "$GRAMMAR_WORK"/
copy_regressions "$GRAMMAR_WORK"

INTERP_WORK="$BUILD/corpus-interp"
rm -rf "$INTERP_WORK"
mkdir -p "$INTERP_WORK"
cp "$REPO"/tests/fuzz/corpus/* "$INTERP_WORK"/
cp "$REPO"/tests/fuzz/corpus_interp/* "$INTERP_WORK"/
for program in "$REPO"/programs/*/*.nc; do
  folder="$(dirname "$program")"
  machine=portal_3x
  [[ -f "$folder/machine" ]] && machine="$(head -n 1 "$folder/machine" | tr -d '[:space:]')"
  { machine_byte "$machine"; cat "$program"; } >"$INTERP_WORK/program_$(basename "$program")"
done
copy_regressions "$INTERP_WORK"

export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# -seed fixed: the same build and corpus give the same run (deterministic CI).
run_fuzzer() {  # run_fuzzer TARGET WORK [EXTRA OPTIONS...]
  echo "== $1, $SECONDS_TO_RUN s"
  "$BUILD/tests/$1" "$2" -max_total_time="$SECONDS_TO_RUN" -max_len=8192 \
    -timeout=10 -rss_limit_mb=2048 -seed=1 -print_final_stats=1 \
    -artifact_prefix="$ARTIFACTS/${1#fuzz_}-" "${@:3}"
}

status=0
run_fuzzer fuzz_grammar "$GRAMMAR_WORK" || status=1
run_fuzzer fuzz_interp "$INTERP_WORK" -dict="$REPO/tests/fuzz/interp.dict" || status=1
exit $status
