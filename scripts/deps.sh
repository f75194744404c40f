#!/usr/bin/env bash
# Installs the Debian 12 packages ncsim needs to build and test (python3-numpy: the trajectory
# checker, tests/checker; munge, slurmctld, slurmd, slurm-client: the single-node Slurm that
# tests/cli/study_slurm_test.sh starts and stops itself, docs/study.md), if any is missing, then the
# report's charting library (report/web: `npm ci` from the pinned package-lock.json, when
# node_modules does not match it). Idempotent; needs root only when a package must be installed.
set -euo pipefail

packages=(
  cmake ninja-build g++ clang libclang-rt-14-dev clang-format
  tao-pegtl-dev libcli11-dev doctest-dev libeigen3-dev libbenchmark-dev
  libtomlplusplus-dev libglpk-dev chromium python3 python3-numpy
  munge slurmctld slurmd slurm-client
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
# npm (with node) from Debian unless an npm is already there (another node build ships its own,
# and Debian's npm package would conflict with it).
command -v npm >/dev/null 2>&1 || missing+=(nodejs npm)
if ((${#missing[@]} > 0)); then
  if [[ $(id -u) -ne 0 ]]; then
    echo "scripts/deps.sh: these packages are missing and installing them needs root: ${missing[*]}" >&2
    exit 2
  fi
  echo "scripts/deps.sh: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# uPlot for the HTML report (report/CMakeLists.txt inlines it): installed again only when the
# lock file changed since the last install.
web=$(cd "$(dirname "$0")/../report/web" && pwd)
if ! cmp -s "$web/package-lock.json" "$web/node_modules/.package-lock.json.installed" 2>/dev/null; then
  echo "scripts/deps.sh: npm ci in report/web"
  (cd "$web" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error >/dev/null)
  cp "$web/package-lock.json" "$web/node_modules/.package-lock.json.installed"
fi
