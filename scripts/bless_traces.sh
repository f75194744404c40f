#!/usr/bin/env bash
# scripts/bless_traces.sh [NCSIM]: rewrites every golden trace programs/<name>/<name>.trace as
# `ncsim trace --max-commands 400` prints it (interp::kGoldenCommands). Blessing is explicit:
# review the change with `git diff programs/` before committing it.
set -euo pipefail
cd "$(dirname "$0")/.."
ncsim=${1:-build/release/cli/ncsim}
[[ -x $ncsim ]] || { echo "bless_traces.sh: no ncsim at $ncsim (build it first)" >&2; exit 2; }
for dir in programs/*/; do
  name=$(basename "$dir")
  [[ -f $dir/$name.nc ]] || continue
  # A program error is part of the record (last line "# ID line N"): status 1 is expected.
  "$ncsim" trace --max-commands 400 "$dir/$name.nc" >"$dir/$name.trace.tmp" 2>/dev/null || true
  mv "$dir/$name.trace.tmp" "$dir/$name.trace"
  echo "blessed $dir$name.trace"
done
