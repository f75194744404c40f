#!/usr/bin/env bash
# scripts/build.sh DIR [cmake options...]: configure and build ncsim into DIR with Ninja.
set -euo pipefail
dir=$1
shift
cmake -S "$(dirname "$0")/.." -B "$dir" -G Ninja -DNCSIM_WERROR=ON "$@" >/dev/null
cmake --build "$dir" -j"$(nproc)"
