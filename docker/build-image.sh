#!/usr/bin/env bash
# Builds the service's image (docker/Dockerfile, tag fosls-contact:latest) and the PostgreSQL
# image of the compose cluster (docker/postgres/Dockerfile, tag fosls-postgres:15), with
# Docker where a Docker engine answers and podman + runc otherwise. Without Docker it needs no
# image registry: the Debian 12 base image is made from Debian's packages when it is missing
# (docker/container-engine.sh). Installs what it needs (podman, runc, mmdebstrap, ...) from
# Debian's packages, quietly and only when missing.
#
#   docker/build-image.sh            # both images; the first build compiles for ~20 minutes
#   docker/build-image.sh --no-cache # rebuild every layer (a cold build)
# Extra arguments go to `build` of both images.
set -euo pipefail
cd "$(dirname "$0")/.."
source docker/container-engine.sh
select_container_engine
ensure_base_image

build_args=("$@")
# The machine's certificate authorities, for npm's HTTPS in the build (docker/Dockerfile).
ca_bundle=/etc/ssl/certs/ca-certificates.crt
[[ -s "${ca_bundle}" ]] && build_args+=(--secret "id=ca-bundle,src=${ca_bundle}")
if [[ "${engine_name}" == podman ]]; then
  # BuildKit reads docker/Dockerfile.dockerignore by itself; podman is told. Docker's image
  # format keeps HEALTHCHECK (podman's default OCI format drops it).
  build_args+=("${engine_run_args[@]}" --ignorefile docker/Dockerfile.dockerignore --format docker)
fi

started=${SECONDS}
"${engine[@]}" build "${build_args[@]}" -f docker/postgres/Dockerfile -t fosls-postgres:15 docker/postgres
"${engine[@]}" build "${build_args[@]}" -f docker/Dockerfile -t fosls-contact:latest .
elapsed=$((SECONDS - started))

size() { "${engine[@]}" image inspect --format '{{.Size}}' "$1" | awk '{printf "%.0f MB", $1 / 1e6}'; }
run=("${engine[@]}" run "${engine_run_args[@]}")
cat <<MSG
built fosls-contact:latest ($(size fosls-contact:latest)) and fosls-postgres:15 ($(size fosls-postgres:15)) with ${engine_name} in $((elapsed / 60)) min $((elapsed % 60)) s

run the service (http://127.0.0.1:8080, jobs in the volume fosls-data):
  ${run[*]} -d --name fosls -p 127.0.0.1:8080:8080 -v fosls-data:/var/lib/fosls/data fosls-contact:latest --workers 2
  ${engine[*]} stop -t 30 fosls        # running solves go back to the queue
run the cluster (PostgreSQL, API on http://127.0.0.1:8081, two workers):
MSG
if [[ "${engine_name}" == podman ]]; then
  echo "  podman-compose --podman-args='--runtime runc' --podman-run-args='${engine_run_args[*]}' -f docker/compose.yaml up -d postgres api worker"
else
  echo "  docker compose -f docker/compose.yaml --profile cluster up -d api worker"
fi
echo "test both: docker/test-image.sh"
