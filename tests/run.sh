#!/usr/bin/env bash
# The README's test command: installs what is missing (Debian 12 packages, the web page's npm
# packages), builds everything and runs the whole test suite (ctest: unit, verification,
# solver, validation, integration, web, style). Extra arguments go to ctest, e.g. -L unit.
set -euo pipefail
cd "$(dirname "$0")/.."
docker/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j2 "$@"
