#!/usr/bin/env bash
# The main job on a bundled conveyor example: install what is missing, build ncsim, then check,
# time (with the audit), run and report programs/conveyor_squares (three sheets on a moving belt,
# each measured, caught up, cut while it moves and left), and print where the report is.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
bash scripts/build.sh build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
# The conveyor example (programs/conveyor_squares, its machine and scenario.toml from the folder):
# three sheets on a CNC-driven belt, each measured, caught up, cut while it moves, and left.
example=programs/conveyor_squares/conveyor_squares.nc
echo "\$ ncsim check $example"
build/release/cli/ncsim check "$example"
echo
echo "\$ ncsim time --audit $example"
build/release/cli/ncsim time --audit "$example"
echo
csv=build/release/conveyor_squares.csv
echo "\$ ncsim run --detail --every 100 -o $csv $example"
build/release/cli/ncsim run --detail --every 100 -o "$csv" "$example"
echo "trajectory: $csv ($(grep -vc '^#' "$csv") lines, the belt's display variables included)"
echo
# The HTML run report of the same program (docs/report.md): one self-contained page, and a
# screenshot of it by headless Chromium; both in the build folder, out of the repository.
report=build/release/conveyor_squares.html
echo "\$ ncsim report -o $report $example"
build/release/cli/ncsim report -o "$report" "$example"
shot=build/release/conveyor_squares.png
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
echo "report: $PWD/$report"
echo "open in a browser: file://$PWD/$report"
