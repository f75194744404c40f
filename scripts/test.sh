#!/usr/bin/env bash
# Every test: install what is missing, then
#   1. format check (clang-format),
#   2. g++ build (RelWithDebInfo) with warnings as errors and AddressSanitizer +
#      UndefinedBehaviorSanitizer, all tests under them (one build: a second one without the
#      sanitizers compiled the same code with the same warnings and ran the same tests, an
#      estimated 15-20 of CI's 50 minutes),
#   3. clang libFuzzer build, the grammar and the interpreter fuzzer for $NCSIM_FUZZ_SECONDS
#      (default 60) seconds each.
# Ends with one line "tests: N passed, M failed" over the test run and the fuzzers.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh

echo "== format check"
mapfile -t sources < <(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find . -name '*.[ch]pp' -not -path './build*')
clang-format --dry-run --Werror "${sources[@]}"

passed=0
failed=0
run_ctest() {  # run_ctest BUILD_DIR: runs ctest, adds its counts to the totals
  local log
  log=$(mktemp)
  local status=0
  ctest --test-dir "$1" --output-on-failure -j"$(nproc)" 2>&1 | tee "$log" || status=1
  local line
  line=$(grep -E 'tests passed, [0-9]+ tests failed out of [0-9]+' "$log" | tail -n 1 || true)
  rm -f "$log"
  if [[ -z $line ]]; then
    echo "ctest in $1 printed no summary" >&2
    failed=$((failed + 1))
    return 1
  fi
  local total fail
  total=$(sed -E 's/.*out of ([0-9]+).*/\1/' <<<"$line")
  fail=$(sed -E 's/.*tests passed, ([0-9]+) tests failed.*/\1/' <<<"$line")
  passed=$((passed + total - fail))
  failed=$((failed + fail))
  return $status
}

overall=0
echo "== g++, warnings as errors, AddressSanitizer + UndefinedBehaviorSanitizer"
bash scripts/build.sh build/ci-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNCSIM_SANITIZE=ON
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  run_ctest build/ci-asan || overall=1

echo "== grammar and interpreter fuzzers, ${NCSIM_FUZZ_SECONDS:-60} s each"
if bash tests/fuzz/run.sh "${NCSIM_FUZZ_SECONDS:-60}"; then
  passed=$((passed + 1))
else
  failed=$((failed + 1))
  overall=1
fi

echo "tests: $passed passed, $failed failed"
exit $overall
