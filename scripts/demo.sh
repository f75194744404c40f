#!/usr/bin/env bash
# The main job on a bundled conveyor example: install what is missing, build ncsim, then check,
# time (with the audit), run and report programs/conveyor_squares (three sheets on a moving belt,
# each measured, caught up, cut while it moves and left), and print where the report is; then
# the reports of one bundled example of each other kind of machine and of each bundled production
# line (programs/lines/), with screenshots.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
# Only the command it runs, not the tests (issue 36: the main job compiled every test).
NCSIM_TARGET=ncsim bash scripts/build.sh build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
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
# screenshot PAGE PNG: headless Chromium's picture of a report page (empty when it fails).
screenshot() {
  rm -f "$2"
  command -v chromium >/dev/null 2>&1 || return 0
  timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-dev-shm-usage \
    --user-data-dir="$PWD/build/release/chromium-profile" --virtual-time-budget=10000 \
    --window-size=1280,2400 --screenshot="$PWD/$2" "file://$PWD/$1" >/dev/null 2>&1 || true
}
shot=build/release/conveyor_squares.png
screenshot "$report" "$shot"
if [[ -s $shot ]]; then
  echo "screenshot: $PWD/$shot"
else
  echo "screenshot: not made (chromium missing or failed; scripts/deps.sh installs it)"
fi
echo
# The other bundled examples, one of each kind of machine: their reports and screenshots in
# build/release/reports (a run-time error would be on its page; each of these runs through).
mkdir -p build/release/reports
echo "reports of the other bundled examples (build/release/reports):"
for name in laser_coil pick_and_place_50 static_saw override_above_100 dense_cam; do
  page=build/release/reports/$name.html
  build/release/cli/ncsim report -o "$page" "programs/$name/$name.nc" >/dev/null
  screenshot "$page" "build/release/reports/$name.png"
  printf '  %-22s %s%s\n' "$name" "$PWD/$page" \
    "$([[ -s build/release/reports/$name.png ]] && echo ' (+ .png)')"
done
# The bundled production lines (programs/lines/, docs/lines.md): each line's page (the belt, the
# workpieces' timeline, each channel's lanes and run report) and its screenshot.
echo "line reports of the bundled production lines (build/release/reports):"
for folder in programs/lines/*/; do
  name=line_$(basename "$folder")
  page=build/release/reports/$name.html
  build/release/cli/ncsim line report "${folder}line.toml" -o "$page" >/dev/null
  screenshot "$page" "build/release/reports/$name.png"
  printf '  %-22s %s%s\n' "$name" "$PWD/$page" \
    "$([[ -s build/release/reports/$name.png ]] && echo ' (+ .png)')"
done
echo
echo "report: $PWD/$report"
echo "open in a browser: file://$PWD/$report"
