#!/usr/bin/env bash
# The main job on a bundled example: install what is missing, build ncsim, check the pick &
# place program of the conveyor-tracking manual (seed 004, section 4.9.2) on its delta robot,
# print the start of what the decoder makes of it; then time and run the NC language's
# reference example on the path interpolator.
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
echo
# The path interpolator runs programs without conveyor, INDP or kinematic commands so far
# (the others answer "not supported", README); the reference example of the NC language runs.
example=programs/isg_reference_example/isg_reference_example.nc
echo "\$ ncsim time --audit $example"
build/release/cli/ncsim time --audit "$example"
echo
echo "\$ ncsim run --every 500 -o build/release/isg_reference_example.csv $example"
build/release/cli/ncsim run --every 500 -o build/release/isg_reference_example.csv "$example"
echo "trajectory: build/release/isg_reference_example.csv ($(grep -vc '^#' build/release/isg_reference_example.csv) lines)"
