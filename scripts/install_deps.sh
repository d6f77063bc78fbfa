#!/usr/bin/env bash
# Installs the Debian packages the package needs, if they are missing.
set -euo pipefail
packages="g++ cmake make libcgal-dev libcgal-qt5-dev libboost-dev libgmp-dev libmpfr-dev libtbb-dev nlohmann-json3-dev libsimdjson-dev libgeos-dev clang doxygen chromium python3-pil"
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "installing:$missing"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq $missing
fi
