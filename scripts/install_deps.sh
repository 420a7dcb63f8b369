#!/usr/bin/env bash
# Installs the Debian 12 packages tehl needs; idempotent: does nothing when all are present.
set -euo pipefail
PKGS=(
  build-essential cmake pkg-config
  libeigen3-dev libsuitesparse-dev liblapack-dev libfftw3-dev libhdf5-dev hdf5-tools
  libtoml11-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev   # libFuzzer target and its sanitizers (tests/fuzz, scripts/ci_extra.sh)
  libopenmpi-dev openmpi-bin
  python3 python3-matplotlib python3-h5py python3-numpy
)
missing=()
for p in "${PKGS[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "install_deps: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
