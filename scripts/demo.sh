#!/usr/bin/env bash
# The main job on a bundled example: install what is missing, build ncsim, check the pick &
# place program of the conveyor-tracking manual (seed 004, section 4.9.2) on its delta robot,
# and print the start of what the decoder makes of it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
program=programs/pick_and_place/pick_and_place.nc
echo "\$ ncsim check $program"
build/release/cli/ncsim check "$program"
echo
echo "\$ ncsim trace --max-commands 12 $program"
build/release/cli/ncsim trace --max-commands 12 "$program"
