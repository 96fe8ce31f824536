#!/usr/bin/env bash
# Install the Debian packages springblock needs, or print the exact command when not root.
# Called by every Makefile entry point, so a fresh Debian machine needs nothing else.
set -euo pipefail

packages=(cmake g++ make git libeigen3-dev libgsl-dev libgtest-dev libbenchmark-dev libcli11-dev
          nlohmann-json3-dev libfmt-dev gnuplot-nox python3-matplotlib python3-numpy python3-scipy
          universal-ctags pybind11-dev python3-pybind11 python3-pytest python3-pandas
          libopenmpi-dev openmpi-bin libtomlplusplus-dev
          python3-sphinx python3-myst-parser chromium python3-websocket)
[ "${SPRINGBLOCK_WITH_CLANG:-0}" = 1 ] && packages+=(clang)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

line="apt-get update && apt-get install -y --no-install-recommends ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  echo "springblock: installing missing Debian packages: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
else
  echo "springblock: missing Debian packages: ${missing[*]}" >&2
  echo "Install them with:  sudo $line" >&2
  exit 1
fi
