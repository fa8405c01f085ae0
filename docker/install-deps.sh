#!/usr/bin/env bash
# Installs the Debian 12 packages this project needs, and only those that are missing:
# `apt-get update` runs only when something has to be installed. Quiet; safe to re-run.
#
#   docker/install-deps.sh           # everything: build, tests, web tests, load tests
#   docker/install-deps.sh --build   # only what compiling and the C++ tests need (Docker)
#   docker/install-deps.sh --container  # what docker/build-image.sh and test-image.sh need
#   docker/install-deps.sh --check   # list what is missing; exit 1 if anything is
set -euo pipefail

build_packages=(
  build-essential cmake pkg-config ccache
  libeigen3-dev libsuitesparse-dev libcpp-httplib-dev nlohmann-json3-dev libsqlite3-dev
  libgmsh-dev libmuparser-dev libcli11-dev libgtest-dev libopenblas-dev
  libpq-dev zlib1g-dev
)
tool_packages=(clang-format curl sqlite3 nodejs npm chromium wrk python3 python3-matplotlib python3-numpy)
# The PostgreSQL job store's tests start a throwaway server (initdb, postgres).
tool_packages+=(postgresql)
# The contract tests validate documents against the published JSON Schemas.
tool_packages+=(python3-jsonschema)
# The gmsh program of the own-mesh workflow in docs/case-format.md (its test runs it).
tool_packages+=(gmsh)

# Building and running the image without Docker or an image registry (docker/build-image.sh):
# podman with runc, mmdebstrap for the Debian base image, podman-compose for the cluster,
# netavark + aardvark-dns (+ iptables, which netavark runs) so that the compose services find
# each other by name.
container_packages=(podman runc mmdebstrap podman-compose netavark aardvark-dns iptables curl python3)

check_only=0
case "${1:-}" in
  --build) packages=("${build_packages[@]}") ;;
  --container) packages=("${container_packages[@]}") ;;
  --check) packages=("${build_packages[@]}" "${tool_packages[@]}") check_only=1 ;;
  "") packages=("${build_packages[@]}" "${tool_packages[@]}") ;;
  *)
    echo "usage: $0 [--build | --container | --check]" >&2
    exit 2
    ;;
esac

# A tool counts as present when its command is on PATH even if another package provides it
# (e.g. NodeSource's nodejs bundles npm and conflicts with Debian's npm package).
provides_command() {
  case "$1" in
    nodejs) command -v node >/dev/null ;;
    npm | chromium | wrk | curl | sqlite3 | clang-format | cmake | python3 | ccache | gmsh) command -v "$1" >/dev/null ;;
    *) return 1 ;;
  esac
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" &&
    ! provides_command "$p"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
if [ "$check_only" -eq 1 ]; then
  echo "missing: ${missing[*]}"
  exit 1
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  as_root=(sudo)
fi
echo "installing: ${missing[*]}"
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
  --no-install-recommends -o Dpkg::Use-Pty=0 "${missing[@]}" >/dev/null
