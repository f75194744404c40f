#!/usr/bin/env bash
# report/render_test.sh NCSIM SOURCE_DIR WORK_DIR: renders the report of a bundled example in
# headless Chromium (Debian's `chromium`) and fails on any console message, script error or
# empty chart. The page marks #ncsim-status data-state="ready" once every chart has drawn with
# > 0 points (report/page.js); any error turns it to "error".
# Exit 77 (ctest: skipped) only when chromium is absent and CI is not set; in CI it fails.
set -euo pipefail
ncsim=$1
src=$2
work=$3
browser=$(command -v chromium || command -v chromium-browser || true)
if [[ -z $browser ]]; then
  if [[ -n ${CI:-} ]]; then
    echo "render_test: chromium is not installed but CI is set (scripts/deps.sh installs it)" >&2
    exit 1
  fi
  echo "render_test: SKIPPED: chromium is not installed (apt-get install chromium, or scripts/deps.sh)"
  exit 77
fi
mkdir -p "$work"
work=$(cd "$work" && pwd)  # file:// needs an absolute path
# render NAME PAGE: the page in headless Chromium; sets `marker` (the status element), `dom` and
# `log`; fails unless every chart drew without error.
render() {
  local example=$1 page=$2
  dom=$work/$example.dom.html
  log=$work/$example.chromium.log
  # Its own profile directory: no state from another run, nothing written to $HOME.
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage \
    --user-data-dir="$work/profile" --enable-logging=stderr --v=0 \
    --virtual-time-budget=10000 --window-size=1280,900 \
    --dump-dom "file://$page" >"$dom" 2>"$log" || {
    echo "render_test: chromium failed for $example:" >&2
    tail -n 20 "$log" >&2
    exit 1
  }
  marker=$(grep -o '<div id="ncsim-status"[^>]*>[^<]*' "$dom" || true)
  echo "render_test: $example: $marker"
  if ! grep -q 'data-state="ready"' <<<"$marker" || ! grep -q 'data-errors="0"' <<<"$marker" ||
    ! grep -q 'data-empty="0"' <<<"$marker"; then
    echo "render_test: $example: the page did not draw every chart without error" >&2
    exit 1
  fi
}

# The README's old example, a run that ends in a run-time error (its page shows the error), and
# the conveyor example (its PCS1 toolpath panels).
for program in programs/isg_reference_example/isg_reference_example.nc tests/cli/soft_limit.nc \
  programs/conveyor_squares/conveyor_squares.nc; do
  example=$(basename "$program" .nc)
  page=$work/$example.html
  status=0
  "$ncsim" report "$src/$program" -o "$page" >/dev/null 2>&1 || status=$?
  # A run-time error still writes the page (exit 1); a usage error (2) writes none.
  if [[ $status -ne 0 && $status -ne 1 ]] || [[ ! -s $page ]]; then
    echo "render_test: ncsim report failed ($status) for $example" >&2
    exit 1
  fi
  render "$example" "$page"
  charts=$(sed -E 's/.*data-charts="([0-9]+)".*/\1/' <<<"$marker")
  if ((charts < 5)); then
    echo "render_test: $example: only $charts charts" >&2
    exit 1
  fi
  # The conveyor example: its conveyor charts (belt velocity, current_pos_master, ...) drew
  # with points (an empty one turns the state to error above), the sync phases are shaded, the
  # workspace is drawn on the toolpath panels and the per-workpiece table has its three sheets.
  if [[ $example == conveyor_squares ]]; then
    conv=$(sed -E 's/.*data-conveyor="([0-9]+)".*/\1/' <<<"$marker")
    bands=$(sed -E 's/.*data-bands="([0-9]+)".*/\1/' <<<"$marker")
    if ! grep -q 'data-workpieces="3"' <<<"$marker"; then
      echo "render_test: $example: the per-workpiece table has not its three rows" >&2
      exit 1
    fi
    if ! [[ $conv =~ ^[0-9]+$ ]] || ((conv < 2)) || ! [[ $bands =~ ^[0-9]+$ ]] || ((bands < 3)) ||
      ! grep -q 'data-workspace="1"' <<<"$marker"; then
      echo "render_test: $example: conveyor charts '$conv' (>= 2), phase bands '$bands' (>= 3)," \
        "workspace drawn: no" >&2
      exit 1
    fi    # The audit's documented steps apart: its 18 VELOJUMP corners, the closest to its formula.
    if ! grep -q '<td class="l">VELOJUMP</td><td>18</td><td class="l">C0 min(A+, |A-|) T</td>' \
      "$dom"; then
      echo "render_test: $example: the audit's table of documented steps is missing" >&2
      exit 1
    fi
  fi
  # The page logs nothing: any console line Chromium reports is an error.
  if grep -E ':CONSOLE|Uncaught' "$log"; then
    echo "render_test: $example: console messages (above)" >&2
    exit 1
  fi
done
# The bundled production lines (docs/report.md "The line page"): one page per line, every
# channel's charts, the workpieces' timeline (one mark per workpiece) and the channel lanes.
for folder in programs/lines/two_pickers programs/lines/laser_sorter programs/lines/arm_picker; do
  example=line_$(basename "$folder")
  page=$work/$example.html
  "$ncsim" line report "$src/$folder/line.toml" -o "$page" >/dev/null 2>&1 || {
    echo "render_test: ncsim line report failed for $example" >&2
    exit 1
  }
  render "$example" "$page"
  arrived=$("$ncsim" line time --json "$src/$folder/line.toml" | python3 -c \
    'import json, sys; print(json.load(sys.stdin)["workpieces"]["arrived"])')
  if ! grep -q 'data-line-channels="2"' <<<"$marker" ||
    ! grep -q "data-timeline=\"$arrived\"" <<<"$marker" ||
    grep -q 'data-lanes="0"' <<<"$marker"; then
    echo "render_test: $example: not both channels, not one timeline mark per workpiece" \
      "($arrived), or no lane drawn" >&2
    exit 1
  fi
  if grep -E ':CONSOLE|Uncaught' "$log"; then
    echo "render_test: $example: console messages (above)" >&2
    exit 1
  fi
done
echo "render_test: ok"
