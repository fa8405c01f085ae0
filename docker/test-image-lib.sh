# Helpers of docker/test-image.sh (sourced after docker/container-engine.sh): HTTP calls with
# curl, JSON with python3, the compose command of the engine, and the cleanup.

say() { echo "test-image: $*"; }
fail() {
  echo "test-image: FAILED: $*" >&2
  exit 1
}
now_ms() { date +%s%3N; }

free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# json_at FILE KEY... : the value at that path (lists take indices), JSON for objects/lists.
json_at() {
  python3 - "$@" <<'PY'
import json, sys
value = json.load(open(sys.argv[1]))
for key in sys.argv[2:]:
    value = value[int(key)] if isinstance(value, list) else value[key]
print(json.dumps(value) if isinstance(value, (dict, list)) else value)
PY
}

wait_healthy() { # BASE SECONDS
  local deadline=$((SECONDS + $2))
  until curl -fsS -o /dev/null "$1/healthz" 2>/dev/null; do
    ((SECONDS < deadline)) || fail "$1/healthz not healthy after $2 s"
    sleep 0.1
  done
}

post_case() { # BASE FILE [IDEMPOTENCY-KEY] -> job id
  local key=() out
  [[ -n "${3:-}" ]] && key=(-H "Idempotency-Key: ${run_id}-$3")
  out="$(curl -fsS -H 'Content-Type: application/json' "${key[@]}" --data-binary "@$2" "$1/v1/jobs")" ||
    fail "POST $1/v1/jobs refused $2"
  python3 -c 'import json, sys; print(json.loads(sys.argv[1])["id"])' "${out}"
}

job_field() { # BASE ID FIELD
  curl -fsS "$1/v1/jobs/$2" | python3 -c 'import json, sys; print(json.load(sys.stdin)[sys.argv[1]])' "$3"
}

wait_state() { # BASE ID STATE SECONDS
  local deadline=$((SECONDS + $4)) state
  while true; do
    state="$(job_field "$1" "$2" state)" || state=unreachable
    [[ "${state}" == "$3" ]] && return 0
    case "${state}" in
      succeeded | failed | cancelled) fail "job $2 ended ${state}, expected $3: $(curl -sS "$1/v1/jobs/$2")" ;;
    esac
    ((SECONDS < deadline)) || fail "job $2 still ${state} after $4 s"
    sleep 0.2
  done
}

# The service's result and the command line program's for the same case: the same force
# (same binary, same solver), pushing up (F_y > 0, docs/result-format.md) and symmetric.
check_hertz_result() { # SERVICE-RESULT CLI-RESULT
  python3 - "$1" "$2" <<'PY' || fail "the Hertz result is wrong"
import json, sys
service, cli = (json.load(open(p)) for p in sys.argv[1:3])
fx, fy = service["contact"]["force"]
cx, cy = cli["contact"]["force"]
problems = []
if service.get("converged") is not True:
    problems.append(f"not converged: {service.get('stop_reason')}")
if not fy > 0:
    problems.append(f"F_y = {fy}, expected > 0")
if abs(fx) > 1e-3 * abs(fy):  # the mesh is symmetric only up to gmsh's meshing
    problems.append(f"F_x = {fx} not ~0 against F_y = {fy}")
if abs(fy - cy) > 1e-9 * abs(cy) or abs(fx - cx) > 1e-9 * abs(cy):
    problems.append(f"force {[fx, fy]} differs from the command line's {[cx, cy]}")
for p in problems:
    print("test-image:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
}

check_vtu() { # FILE
  head -c 200 "$1" | grep -q '<VTKFile' || fail "$1 is not a VTK XML file"
  grep -q '</VTKFile>' "$1" || fail "$1 is cut short"
}

compose() {
  if [[ "${engine_name}" == podman ]]; then
    podman-compose --podman-args='--runtime runc' --podman-run-args="${engine_run_args[*]}" \
      -p "${project}" -f docker/compose.yaml "$@"
  else
    docker compose -p "${project}" -f docker/compose.yaml --profile cluster "$@"
  fi
}

compose_containers() { # SERVICE -> container names
  "${engine[@]}" ps -a --filter "label=com.docker.compose.project=${project}" \
    --filter "label=com.docker.compose.service=$1" --format '{{.Names}}' | sort
}

# Every job succeeded, the workers' logs store each one's success exactly once, and the API
# lists exactly these jobs.
check_succeeded_once() { # API SCRATCH IDS...
  local api="$1" scratch="$2"
  shift 2
  for j in "$@"; do
    [[ "$(job_field "${api}" "${j}" state)" == succeeded ]] || fail "job ${j} is not succeeded"
  done
  curl -fsS "${api}/v1/jobs?page_size=100" > "${scratch}/list.json"
  python3 - "${scratch}/list.json" "$@" "${scratch}"/log-* <<'PY' || fail "not every job succeeded exactly once"
import json, sys, collections
listed = json.load(open(sys.argv[1]))
ids = [int(a) for a in sys.argv[2:] if a.isdigit()]
logs = [a for a in sys.argv[2:] if not a.isdigit()]
stored = collections.Counter()
for path in logs:
    for line in open(path, errors="replace"):
        try:
            e = json.loads(line)
        except ValueError:
            continue
        if isinstance(e, dict) and e.get("event") == "job_transition" \
                and e.get("to") == "succeeded" and e.get("stored") is True:
            stored[e["job_id"]] += 1
problems = [f"job {j}: stored as succeeded {stored[j]} times" for j in ids if stored[j] != 1]
problems += [f"job {j}: stored but not posted by this test" for j in stored if j not in ids]
listed_ids = sorted(job["id"] for job in listed["jobs"])
if listed_ids != sorted(ids) or listed["next_page_token"] is not None:
    problems.append(f"the API lists {len(listed_ids)} jobs, expected the {len(ids)} posted")
for p in problems:
    print("test-image:", p, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
}

# Removes what this run made; on failure first shows the end of every container's log.
cleanup() {
  local status=$? c
  set +e
  local made=("${single}")
  mapfile -t -O 1 made < <("${engine[@]}" ps -a --format '{{.Names}}' \
    --filter "label=com.docker.compose.project=${project}")
  if [[ ${status} -ne 0 ]]; then
    [[ -s "${scratch}/engine.log" ]] && { echo "---- the engine's messages" && tail -n 40 "${scratch}/engine.log"; } >&2
    for c in "${made[@]}"; do
      "${engine[@]}" container inspect "${c}" >/dev/null 2>&1 || continue
      echo "---- last lines of ${c}" >&2
      "${engine[@]}" logs --tail 25 "${c}" >&2 2>&1
    done
  fi
  for c in "${made[@]}"; do "${engine[@]}" rm -f -v "${c}" >/dev/null 2>&1; done
  compose down -v >/dev/null 2>&1
  "${engine[@]}" volume rm -f "${volume}" "${project}_fosls-data" "${project}_fosls-postgres" >/dev/null 2>&1
  "${engine[@]}" network rm -f "${project}_default" >/dev/null 2>&1
  [[ "${engine_name}" == podman ]] && podman pod rm -f "pod_${project}" >/dev/null 2>&1
  rm -rf "${scratch}"
  exit "${status}"
}
