#!/usr/bin/env bash
# scripts/bless_goldens.sh [NCSIM]: rewrites the golden trajectory of every program in
# programs/ (`ncsim golden bless --all`, docs/golden.md). Blessing is explicit: review the
# change with `git diff --stat programs/` and `git diff programs/` before committing it, in a
# commit of its own that says why the trajectories moved.
set -euo pipefail
cd "$(dirname "$0")/.."
ncsim=${1:-build/release/cli/ncsim}
[[ -x $ncsim ]] || { echo "bless_goldens.sh: no ncsim at $ncsim (build it first)" >&2; exit 2; }
"$ncsim" golden bless --all --programs programs
# The real-program library (programs/real/<name>/, issue 33) when it has programs.
if compgen -G "programs/real/*/*.nc" >/dev/null; then
  "$ncsim" golden bless --all --programs programs/real
fi
