# Stopping a worker of the compose cluster while it provably holds a running job: helpers of
# docker/test-image.sh, sourced after test-image-lib.sh (they use `engine`, `compose_containers`,
# `say`, `fail`, `log` and `scratch`). tests/container/worker_stop_test.sh runs them against a
# fake engine.
#
# Which worker holds a job is read from the store, not guessed from the workers' logs: a job is
# running exactly while its lease is held, and the lease owner is "HOST:PID:RANDOM/wN", HOST
# being the worker's host name (in a container, its hostname). A worker's log only says that it
# started a job at some time; the Hertz job takes 0.9 s, so the worker the old test picked from
# its log was often idle again when the stop reached it (issue 50, item 11). Even a lease read
# from the store can end before the stop lands, so the stopped worker's own log decides: it put
# the job back (the test passes), it had finished the job first (the premise did not hold:
# another try), or it still shows the job running (the stop lost it: the test fails).

# running_leases: "JOB LEASE_OWNER" for every running job not asked to cancel, oldest first.
running_leases() {
  "${engine[@]}" exec "$(compose_containers postgres)" psql -U fosls -d fosls -At -F ' ' -c \
    "SELECT id, lease_owner FROM jobs WHERE state = 'running' AND cancel_requested = 0 ORDER BY id"
}

# worker_hosts CONTAINER...: "HOSTNAME CONTAINER" per container.
worker_hosts() {
  local c
  for c in "$@"; do
    printf '%s %s\n' "$("${engine[@]}" inspect --format '{{.Config.Hostname}}' "${c}")" "${c}"
  done
}

# lease_holder LEASES HOSTS: "CONTAINER JOB" for the oldest running job in LEASES (running_leases'
# answer) whose lease a worker of HOSTS (worker_hosts' answer) holds; status 1 when none does.
lease_holder() {
  python3 - "$1" "$2" <<'PY'
import sys
hosts = dict(line.split()[:2] for line in sys.argv[2].splitlines() if len(line.split()) >= 2)
for line in sys.argv[1].splitlines():
    job, _, owner = line.strip().partition(" ")
    host = owner.split(":", 1)[0]
    if job.isdigit() and host in hosts:
        print(hosts[host], job)
        sys.exit(0)
sys.exit(1)
PY
}

# stop_outcome LOG JOB: what a stopped worker's log says of JOB, from its last job_transition:
# "requeued" (running -> queued: put back), "finished" (running -> succeeded, failed or
# cancelled: done before the stop reached it), "running" (started and never put back) or
# "absent" (the log never mentions it).
stop_outcome() {
  python3 - "$1" "$2" <<'PY'
import json, sys
last = None
for line in open(sys.argv[1], errors="replace"):
    try:
        e = json.loads(line)
    except ValueError:
        continue
    if isinstance(e, dict) and e.get("event") == "job_transition" and str(e.get("job_id")) == sys.argv[2]:
        last = e
if last is None:
    print("absent")
elif last.get("to") == "running":
    print("running")
elif last.get("from") == "running" and last.get("to") == "queued":
    print("requeued")
else:
    print("finished")
PY
}

# stop_worker_holding_a_job WORKER...: stops (SIGTERM) one of the workers while the store shows
# it holding a running job and checks that it put that job back in the queue. Sets `victim` and
# `requeued` (that job). Tries again, at most 5 times, when the job finished before the stop
# reached its worker; fails when no worker holds a job for FOSLS_TEST_LEASE_WAIT seconds (120).
stop_worker_holding_a_job() {
  local hosts pair job outcome try wait_s="${FOSLS_TEST_LEASE_WAIT:-120}" deadline
  hosts="$(worker_hosts "$@")"
  for try in 1 2 3 4 5; do
    deadline=$((SECONDS + wait_s))
    until pair="$(lease_holder "$(running_leases)" "${hosts}")"; do
      ((SECONDS < deadline)) || fail "no worker of $* held a running job for ${wait_s} s"
      sleep 0.2
    done
    read -r victim job <<< "${pair}"
    "${engine[@]}" stop -t 30 "${victim}" > /dev/null 2>> "${log}"
    "${engine[@]}" logs "${victim}" > "${scratch}/victim-stop-${try}.log" 2>&1
    outcome="$(stop_outcome "${scratch}/victim-stop-${try}.log" "${job}")"
    case "${outcome}" in
      requeued)
        requeued=("${job}")
        return 0
        ;;
      finished)
        say "cluster: ${victim} finished job ${job} before the stop reached it; once more"
        "${engine[@]}" start "${victim}" > /dev/null 2>> "${log}"
        ;;
      *)
        fail "${victim} held job ${job} (its lease in the store) when it was stopped, but did not" \
          "put it back in the queue (its log: ${outcome})"
        ;;
    esac
  done
  fail "5 stops of a worker holding a job all came after the job had finished"
}
