#!/usr/bin/env bash
# Installs the Debian 12 packages MillExpert needs. Idempotent: installs only what is missing.
set -euo pipefail
PACKAGES=(
  build-essential cmake ninja-build pkg-config
  qt6-base-dev qt6-base-dev-tools libqt6sql6-sqlite libqt6sql6-psql postgresql qt6-svg-dev
  libqcustomplot-dev libeigen3-dev libsundials-dev libfftw3-dev
  libbenchmark-dev xvfb xauth x11-apps xdotool fonts-dejavu-core poppler-utils
  clang-format-14 clang-tidy-14 clang-14 libclang-rt-14-dev libzip-dev git help2man shared-mime-info desktop-file-utils
  slurm-wlm munge openssl python3
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#PACKAGES[@]} packages present"
  exit 0
fi
echo "bootstrap: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
