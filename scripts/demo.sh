#!/usr/bin/env bash
# The main job on a bundled example: install what is missing, build ncsim, check the pick &
# place program of the conveyor-tracking manual (seed 004, section 4.9.2) on its delta robot,
# print the start of what the decoder makes of it; then time and run the NC language's
# reference example on the path interpolator and write its HTML report (and a screenshot).
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
echo
# The HTML run report of the same example (docs/report.md): one self-contained page, and a
# screenshot of it by headless Chromium; both in the build folder, out of the repository.
report=build/release/isg_reference_example.html
echo "\$ ncsim report -o $report $example"
build/release/cli/ncsim report -o "$report" "$example"
shot=build/release/isg_reference_example.png
rm -f "$shot"
if command -v chromium >/dev/null 2>&1; then
  timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-dev-shm-usage \
    --user-data-dir="$PWD/build/release/chromium-profile" --virtual-time-budget=10000 \
    --window-size=1280,2400 --screenshot="$PWD/$shot" "file://$PWD/$report" >/dev/null 2>&1 || true
fi
if [[ -s $shot ]]; then
  echo "screenshot: $PWD/$shot"
else
  echo "screenshot: not made (chromium missing or failed; scripts/deps.sh installs it)"
fi
echo "open in a browser: file://$PWD/$report"
