#!/usr/bin/env bash
# The trajectory checker over thousands of seeded programs (tests/checker/README.md "Bench"):
#   bash bench/checker_set.sh [NCSIM] [FIRST..LAST] [JOBS]
# defaults build/release/cli/ncsim, seeds 1..3000, all cores. Not in CI (the CI set is seeds
# 1..150 with their known findings, tests/checker.cmake). Prints every program with a finding,
# the summary table, and writes the results (JSON) and the findings' tags beside the build;
# exit 1 while issue 36's findings remain.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ncsim=${1:-$root/build/release/cli/ncsim}
seeds=${2:-1..3000}
jobs=${3:-$(nproc)}
out=${CHECKER_OUT:-$root/build/checker-bench}
mkdir -p "$out"
py=/usr/bin/python3
[[ -x $py ]] || py=python3
exec "$py" "$root/tests/checker/run_set.py" --ncsim "$ncsim" --seeds "$seeds" --jobs "$jobs" \
  --json "$out/results.json" --write-expect "$out/tags.txt" --keep "$out/failing"
