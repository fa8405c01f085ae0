#!/usr/bin/env bash
# ctest's `container_image` (tests/container/tests.cmake): only with FOSLS_CONTAINER_TESTS=1,
# since building the image compiles the whole project again inside it.
set -euo pipefail
if [[ "${FOSLS_CONTAINER_TESTS:-0}" != 1 ]]; then
  echo "skipped: set FOSLS_CONTAINER_TESTS=1 to build and test the container image (~20 min)"
  exit 77
fi
cd "$(dirname "$0")/../.."
docker/build-image.sh
docker/test-image.sh
