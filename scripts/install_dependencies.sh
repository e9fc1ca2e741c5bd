#!/bin/bash
# Install the Debian packages levelsinter needs, if any is missing.
# Idempotent and quiet when everything is present. Run as root.
set -euo pipefail
packages="libdeal.ii-dev libeigen3-dev libhdf5-openmpi-dev cmake make g++ openmpi-bin python3 python3-matplotlib python3-h5py"
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "levelsinter: installing Debian packages:$missing"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends $missing > /dev/null
fi
