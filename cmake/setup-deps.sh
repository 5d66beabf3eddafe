#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages Lamina needs, only those that are missing.
# Uses sudo when not root. Safe to run repeatedly: it does nothing when all are present.
#   setup-deps.sh          what the build and `make test` need
#   setup-deps.sh slurm    Slurm and munge for the cluster test (tests/cluster), installed by that
#                          test when they are missing (22.05 in Debian 12; nothing starts by itself)
#   setup-deps.sh peers    MuJoCo 2.2.2 and Bullet 3.24 for lamina-peers (`make peers`)
set -euo pipefail

if [[ ${1:-} == slurm ]]; then
  packages=(slurmctld slurmd slurm-client munge)
elif [[ ${1:-} == peers ]]; then
  packages=(libmujoco-dev libbullet-dev)
else
  packages=(
    build-essential cmake ninja-build pkg-config
    libode-dev libeigen3-dev libfcl-dev libccd-dev libassimp-dev zlib1g-dev
    liburdfdom-dev liburdfdom-headers-dev libtinyxml2-dev libimgui-dev libglfw3-dev
    libosmesa6-dev libegl-dev libstb-dev libgtest-dev libgmock-dev libbenchmark-dev
    libcli11-dev nlohmann-json3-dev
    pybind11-dev python3-pybind11 python3-pytest python3-numpy python3-pil python3-dev
    xvfb xauth xdotool clang-format lld
  )
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

echo "lamina: installing missing packages: ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "lamina: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update -qq
"${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends "${missing[@]}"
