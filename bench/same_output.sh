#!/usr/bin/env bash
# same_output.sh NCSIM OUTDIR [WIDE_MACHINE]
#
# Records what `ncsim check` (full, and --syntax-only) and `ncsim trace` print for every NC
# program of the repository (every .nc file under git, the fuzz corpora and regressions) and
# for the generated bench programs: stdout, stderr and the exit status, one file per program
# and command under OUTDIR. Run it with the ncsim before a speed change and with the one after,
# then `diff -r BEFORE AFTER`: a speed change must leave every byte and exit status as it was.
# The generated programs (bench/gen_program, 20,000 blocks, seeds 1-3) are checked on WIDE_MACHINE
# when given (the +-2 m copy of portal_3x that bench/check_vs_rs274.sh makes), else skipped;
# GEN names the generator (default: bench/gen_program of NCSIM's build).
# Runs from the repository root, so the file names in the output are the same for both runs.
set -euo pipefail

NCSIM="$(realpath "$1")"
OUT="$(realpath -m "$2")"
WIDE="${3:+$(realpath "$3")}"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$REPO"
mkdir -p "$OUT"

record() {  # record NAME CMD...: stdout, stderr and exit status of CMD in OUT/NAME
  local name="$1"
  shift
  mkdir -p "$(dirname "$OUT/$name")"
  set +e
  timeout 600 "$@" >"$OUT/$name.out" 2>"$OUT/$name.err"
  echo "exit $?" >"$OUT/$name.rc"
  set -e
}

mapfile -t programs < <({
  git ls-files '*.nc' '*.NC'
  find tests/fuzz/corpus tests/fuzz/corpus_interp tests/fuzz/regressions -type f ! -name '*.md'
} | sort -u)
for p in "${programs[@]}"; do
  record "$p.check" "$NCSIM" check "$p"
  record "$p.syntax" "$NCSIM" check --syntax-only "$p"
  record "$p.trace" "$NCSIM" trace --max-commands 20000 "$p"
done
if [[ -n "$WIDE" ]]; then
  gen="${GEN:-$(dirname "$NCSIM")/../bench/gen_program}"
  dir="${TMPDIR:-/tmp}/ncsim-same-output"  # the same path in both runs: it is in the output
  mkdir -p "$dir"
  for seed in 1 2 3; do
    nc="$dir/seed$seed.nc"
    "$gen" --blocks 20000 --seed "$seed" --nc "$nc" --ngc /dev/null
    record "gen/seed$seed.check" "$NCSIM" check --machine "$WIDE" "$nc"
    record "gen/seed$seed.trace" "$NCSIM" trace --max-commands 0 --machine "$WIDE" "$nc"
  done
fi
echo "${#programs[@]} programs recorded in $OUT"
