#!/usr/bin/env bash
# The README's test command: installs what is missing (Debian 12 packages, the web page's npm
# packages), builds everything and runs the whole test suite (ctest: unit, verification,
# solver, validation, integration, web, style). Extra arguments go to ctest, e.g. -L unit.
#
#   tests/run.sh --sanitize [ctest args]   the sanitizer configuration instead: a separate build
#       (build-sanitize/, optimised with debug info) with AddressSanitizer,
#       UndefinedBehaviorSanitizer and the FOSLS_ASSERT invariant checks, running the unit and
#       solver tests. Slower (about 3x); not part of CI's default run.
set -euo pipefail
cd "$(dirname "$0")/.."
docker/install-deps.sh
if [[ "${1:-}" == "--sanitize" ]]; then
  shift
  cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFOSLS_SANITIZE=ON >/dev/null
  cmake --build build-sanitize -j"$(nproc)"
  # Leaks: OpenMP's and OpenBLAS's thread pools keep their memory to the end on purpose.
  export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
  exec ctest --test-dir build-sanitize --output-on-failure -j2 -L "unit|solver" "$@"
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j2 "$@"
