#!/usr/bin/env bash
# tests/fuzz/run.sh SECONDS
#
# Builds fuzz_grammar (clang, libFuzzer + ASan + UBSan, RelWithDebInfo) in build/fuzz and runs
# it for SECONDS over a copy of tests/fuzz/corpus/ plus tests/fuzz/regressions/ (the copy and
# every artifact live in build/fuzz/, never in the repository). Exit status: 0 when the run
# ends without a crash, hang (> 10 s per input), leak, out-of-memory or sanitizer report;
# non-zero otherwise, with the crashing input left in build/fuzz/artifacts/.
# CI calls it with 60.
set -euo pipefail

SECONDS_TO_RUN="${1:?usage: tests/fuzz/run.sh SECONDS}"
[[ "$SECONDS_TO_RUN" =~ ^[0-9]+$ ]] || { echo "run.sh: SECONDS must be an integer" >&2; exit 2; }
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="$REPO/build/fuzz"

cmake -S "$REPO" -B "$BUILD" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DNCSIM_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD" -j2 --target fuzz_grammar

WORK="$BUILD/corpus-work"
ARTIFACTS="$BUILD/artifacts"
rm -rf "$WORK"
mkdir -p "$WORK" "$ARTIFACTS"
cp "$REPO"/tests/fuzz/corpus/* "$WORK"/
# Inputs that once crashed are replayed first, as part of the corpus.
find "$REPO/tests/fuzz/regressions" -type f ! -name README.md -exec cp {} "$WORK"/ \;

export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# -seed fixed: the same build and corpus give the same run (deterministic CI).
"$BUILD/tests/fuzz_grammar" "$WORK" -max_total_time="$SECONDS_TO_RUN" -max_len=8192 \
  -timeout=10 -rss_limit_mb=2048 -seed=1 -print_final_stats=1 \
  -artifact_prefix="$ARTIFACTS/"
