#!/usr/bin/env bash
# Installs the Debian 12 packages ncsim needs to build and test, if any is missing.
# Idempotent; needs root only when something must be installed.
set -euo pipefail

packages=(
  cmake ninja-build g++ clang libclang-rt-14-dev clang-format
  tao-pegtl-dev libcli11-dev doctest-dev libeigen3-dev libbenchmark-dev
  libtomlplusplus-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi
if [[ $(id -u) -ne 0 ]]; then
  echo "scripts/deps.sh: these packages are missing and installing them needs root: ${missing[*]}" >&2
  exit 2
fi
echo "scripts/deps.sh: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
