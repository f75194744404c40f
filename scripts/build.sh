#!/usr/bin/env bash
# scripts/build.sh DIR [cmake options...]: configure and build ncsim into DIR with Ninja.
# NCSIM_TARGET=ncsim builds only the command (the main job); unset, everything (the tests).
set -euo pipefail
dir=$1
shift
cmake -S "$(dirname "$0")/.." -B "$dir" -G Ninja -DNCSIM_WERROR=ON "$@" >/dev/null
cmake --build "$dir" -j"$(nproc)" ${NCSIM_TARGET:+--target "$NCSIM_TARGET"}
