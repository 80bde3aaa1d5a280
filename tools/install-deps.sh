#!/usr/bin/env bash
# Installs every Debian 12 package signorini needs to build, test and plot.
# Idempotent and non-interactive; run as root (or with sudo available).
# Usage: bash tools/install-deps.sh   (-h, --help: this text)
set -euo pipefail
source "$(dirname "$0")/script_args.sh"
no_arguments "$@"
if ! command -v dpkg-query > /dev/null || ! command -v apt-get > /dev/null; then
  echo "install-deps: this script installs Debian packages (dpkg and apt-get); on another system install" \
    "Trilinos 13.2, p4est, ExodusII, muParser, GoogleTest and MPI yourself and configure with cmake" \
    "(README: \"Building against another Trilinos\")" >&2
  exit 1
fi
packages=(
  build-essential cmake git pkg-config
  trilinos-all-dev libptscotch-dev
  libopenmpi-dev openmpi-bin
  libp4est-dev libexodusii-dev libnetcdf-dev libmuparser-dev
  libgtest-dev
  python3 python3-matplotlib python3-numpy python3-netcdf4
  python3-paraview
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
