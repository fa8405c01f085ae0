#!/usr/bin/env bash
# The README's run command: installs what is missing, builds, and starts the job service with
# its embedded SQLite database (./data/fosls.db) on http://127.0.0.1:8080. Extra arguments go
# to fosls-serve, e.g. --port 9000 --workers 2.
set -euo pipefail
cd "$(dirname "$0")/.."
docker/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target fosls-serve fosls-contact
web/build.sh --runtime
exec build/bin/fosls-serve "$@"
