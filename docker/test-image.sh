#!/usr/bin/env bash
# Tests the images that docker/build-image.sh built (ctest label `container`), on loopback
# ports that are free, with containers, volumes and networks of its own (all removed at the
# end, also on failure):
#
#  1. One container (SQLite in a volume): waits for /healthz, runs the image's HEALTHCHECK
#     (podman), posts the shipped Hertz case, polls it to `succeeded`, checks the result
#     (converged, the force equal to the command line program's in the same image, F_y > 0,
#     F_x ≈ 0 by symmetry) and the VTU; replaces the container by a new one on the same
#     volume and finds the job and its result there; stops it by name (SIGTERM: exit code 0).
#  2. The compose cluster (PostgreSQL, one API process, two workers): posts 20 jobs, measures
#     jobs per minute; posts a long job (Hertz two refinements finer) and 20 more, stops the
#     worker that holds the lease of a running job in the store (`stop`, SIGTERM: the job goes
#     back to the queue, its attempt not counted; test-image-stop.sh), starts it again, and
#     checks that all 41 jobs end `succeeded`, each stored as succeeded exactly once (from the
#     workers' logs), and that the API lists exactly these 41.
#
# Prints the numbers docs/service.md quotes (cold start to healthy, jobs per minute).
#
#   docker/test-image.sh        # after docker/build-image.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source docker/container-engine.sh
select_container_engine
source docker/test-image-lib.sh
source docker/test-image-stop.sh

image=fosls-contact:latest
for needed in "${image}" fosls-postgres:15; do
  if ! "${engine[@]}" image inspect "${needed}" >/dev/null 2>&1; then
    echo "test-image: no image ${needed}; run docker/build-image.sh first" >&2
    exit 1
  fi
done

run_id="fosls-test-$$"
single="${run_id}-single"
volume="${run_id}-data"
project="foslstest$$" # compose project: its containers, network and volumes carry this name
scratch="$(mktemp -d)"
trap cleanup EXIT
trap "exit 143" TERM INT # through cleanup

# ---------------------------------------------------------------- 1. one container
# The engine's messages go to engine.log (shown on failure): podman without systemd reports on
# every start and stop that it cannot schedule the image's health check.
log="${scratch}/engine.log"
"${engine[@]}" run "${engine_run_args[@]}" --rm --entrypoint fosls-contact "${image}" \
  example hertz > "${scratch}/hertz.json" 2>> "${log}"
# The same case solved by the command line program in the same image: the service must agree.
"${engine[@]}" run "${engine_run_args[@]}" --rm --entrypoint sh "${image}" -c \
  'fosls-contact example hertz > /tmp/h.json &&
   fosls-contact solve /tmp/h.json --out /tmp/r.json --quiet >/dev/null && cat /tmp/r.json' \
  > "${scratch}/cli-result.json" 2>> "${log}"

port="$(free_port)"
base="http://127.0.0.1:${port}"
start_single() {
  "${engine[@]}" run "${engine_run_args[@]}" -d --name "${single}" -p "127.0.0.1:${port}:8080" \
    -v "${volume}:/var/lib/fosls/data" "${image}" --workers 2 >/dev/null 2>> "${log}"
}
started_ms="$(now_ms)"
start_single
wait_healthy "${base}" 120
cold_start_ms=$(($(now_ms) - started_ms))
say "single: healthy ${cold_start_ms} ms after \`run\` (cold start, new volume)"
if [[ "${engine_name}" == podman ]]; then
  podman healthcheck run "${single}" >/dev/null 2>> "${log}" || fail "the image's HEALTHCHECK fails"
  say "single: the image's HEALTHCHECK passes"
fi

job="$(post_case "${base}" "${scratch}/hertz.json")"
wait_state "${base}" "${job}" succeeded 600
curl -fsS "${base}/v1/jobs/${job}/result" > "${scratch}/result.json"
curl -fsS -o "${scratch}/solution.vtu" "${base}/v1/jobs/${job}/solution.vtu"
check_hertz_result "${scratch}/result.json" "${scratch}/cli-result.json"
check_vtu "${scratch}/solution.vtu"
say "single: job ${job} succeeded; force $(json_at "${scratch}/result.json" contact force)" \
  "= the command line's; VTU $(wc -c < "${scratch}/solution.vtu") bytes"

# A new container on the same volume: the job and its result are still there.
"${engine[@]}" stop -t 30 "${single}" >/dev/null 2>> "${log}"
"${engine[@]}" rm "${single}" >/dev/null 2>> "${log}"
started_ms="$(now_ms)"
start_single
wait_healthy "${base}" 120
warm_start_ms=$(($(now_ms) - started_ms))
[[ "$(job_field "${base}" "${job}" state)" == succeeded ]] || fail "job ${job} lost its state"
curl -fsS "${base}/v1/jobs/${job}/result" > "${scratch}/result-again.json"
cmp -s "${scratch}/result.json" "${scratch}/result-again.json" || fail "the result changed"
say "single: a new container on the same volume has job ${job} and its result" \
  "(healthy after ${warm_start_ms} ms)"
"${engine[@]}" stop -t 30 "${single}" >/dev/null 2>> "${log}"
exit_code="$("${engine[@]}" inspect --format '{{.State.ExitCode}}' "${single}")"
[[ "${exit_code}" == 0 ]] || fail "fosls-serve exited with ${exit_code} on SIGTERM"
say "single: stopped by name, exit code 0"

# ---------------------------------------------------------------- 2. the compose cluster
api_port="$(free_port)"
export FOSLS_API_PORT="${api_port}" FOSLS_PORT="$(free_port)"
api="http://127.0.0.1:${api_port}"
started_ms="$(now_ms)"
compose up -d --no-build postgres api worker >> "${log}" 2>&1 || fail "compose up failed"
wait_healthy "${api}" 180
cluster_start_ms=$(($(now_ms) - started_ms))
mapfile -t workers < <(compose_containers worker)
[[ ${#workers[@]} -eq 2 ]] || fail "expected 2 worker containers, found ${#workers[@]}"
api_restarts="$("${engine[@]}" inspect --format '{{.RestartCount}}' "$(compose_containers api)")"
say "cluster: API healthy on ${api} ${cluster_start_ms} ms after \`up\` (restarted" \
  "${api_restarts} times while PostgreSQL started), workers ${workers[*]}"

# Throughput: 20 jobs, both workers, nothing stopped.
started_ms="$(now_ms)"
batch=()
for i in $(seq 1 20); do batch+=("$(post_case "${api}" "${scratch}/hertz.json" "rate-${i}")"); done
for j in "${batch[@]}"; do wait_state "${api}" "${j}" succeeded 900; done
rate_ms=$(($(now_ms) - started_ms))
say "cluster: 20 jobs in $((rate_ms / 1000)).$(((rate_ms % 1000) / 100)) s:" \
  "$(awk -v ms="${rate_ms}" 'BEGIN { printf "%.1f", 20 * 60000 / ms }') jobs per minute"

# Stopping a worker in the middle of a job: a long one (claimed first, the oldest) and 20 more;
# the worker stopped is the one the store shows holding a running job's lease.
python3 -c 'import json, sys; c = json.load(open(sys.argv[1])); c["mesh"]["refinements"] += 2
c["name"] = "hertz-long"; json.dump(c, open(sys.argv[2], "w"))' "${scratch}/hertz.json" \
  "${scratch}/hertz-long.json"
kill_batch=("$(post_case "${api}" "${scratch}/hertz-long.json" "kill-long")")
for i in $(seq 1 20); do kill_batch+=("$(post_case "${api}" "${scratch}/hertz.json" "kill-${i}")"); done
stop_worker_holding_a_job "${workers[@]}"
say "cluster: stopped ${victim} while it held job ${requeued[*]}; it put the job back in the queue"
sleep 2
"${engine[@]}" start "${victim}" >/dev/null 2>> "${log}"
for j in "${kill_batch[@]}"; do wait_state "${api}" "${j}" succeeded 900; done
# A stop is not a crash: the interrupted run does not count as an attempt.
for j in "${requeued[@]}"; do
  attempts="$(job_field "${api}" "${j}" attempts)"
  [[ "${attempts}" == 1 ]] || fail "job ${j}, put back by a stopped worker, has attempts ${attempts}"
done

for w in "${workers[@]}"; do "${engine[@]}" logs "${w}" > "${scratch}/log-${w}" 2>&1; done
check_succeeded_once "${api}" "${scratch}" "${batch[@]}" "${kill_batch[@]}"
say "cluster: all 41 jobs succeeded, each stored once; 41 jobs listed by the API"
echo "test-image: passed (cold start ${cold_start_ms} ms," \
  "$(awk -v ms="${rate_ms}" 'BEGIN { printf "%.1f", 20 * 60000 / ms }') jobs per minute on the cluster)"
