#!/usr/bin/env bash
# Installs the Debian packages this project needs, only those that are missing.
# Fast when everything is already there (dpkg checks only, no apt-get call).
# Runs as root, or through sudo when not root and sudo exists.
set -euo pipefail

packages=(
  cmake g++ make
  libcgal-dev libeigen3-dev
  libboost-dev libboost-graph-dev libboost-test-dev libboost-program-options-dev
  libsuitesparse-dev libopenblas0-serial libtbb-dev libpng-dev
  doxygen python3
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ $status == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo -n)   # never prompt: CI has no stdin
else
  echo "setup: missing packages (${missing[*]}) and not root, no sudo: install them by hand" >&2
  exit 1
fi

export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -q --no-install-recommends "${missing[@]}"
