#!/bin/sh
# Installs what is missing, builds the test suite and the examples, runs them all with CTest.
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_dependencies.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$root/build" -j 2
cd "$root/build" && ctest --output-on-failure -j 2
