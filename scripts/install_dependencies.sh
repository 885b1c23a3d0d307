#!/bin/sh
# Installs the Debian packages the project needs, if any is missing (apt-get; sudo when not root),
# and those named as arguments; with --only, just those named and what they depend on (the main
# job's few, without the packages they recommend).
set -e
packages="libcgal-dev libboost-dev libgmp-dev libmpfr-dev catch2 nlohmann-json3-dev cmake g++ make ccache python3 python3-shapely python3-meshio python3-numpy python3-dev pybind11-dev python3-pytest python3-matplotlib"
recommends=""
if [ "$1" = --only ]; then
  shift
  packages=""
  recommends="--no-install-recommends"
fi
packages="$packages $*"
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "installing:$missing"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $recommends $missing > /dev/null
