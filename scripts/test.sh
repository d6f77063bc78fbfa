#!/usr/bin/env bash
# Builds the package with its tests and runs them with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build-configure.log
cmake --build build -j2
cd build
ctest --output-on-failure -j2
