#!/usr/bin/env bash
# docker/test-image-stop.sh against a fake container engine (ctest `worker_stop_choice`, label
# unit): the cluster test must stop the worker that holds a running job's lease in the store,
# not one that may be idle (issue 50, item 11), try again when the job finished before the stop
# reached it, and fail when a stopped worker did not put its job back. No engine is needed.
set -euo pipefail
cd "$(dirname "$0")/../.."
source docker/test-image-lib.sh
source docker/test-image-stop.sh

scratch="$(mktemp -d)"
trap 'rm -rf "${scratch}"' EXIT
log="${scratch}/engine.log"
project=fake
failures=0

check() { # NAME EXPECTED ACTUAL
  if [[ "$2" == "$3" ]]; then
    echo "ok: $1"
  else
    echo "FAILED: $1: expected '$2', got '$3'" >&2
    failures=$((failures + 1))
  fi
}

transition() { # JOB FROM TO
  printf '{"event":"job_transition","job_id":%s,"from":"%s","to":"%s","attempt":1}\n' "$@"
}

# ---- the pure parts
leases=$'3 0a1b2c3d4e5f:7:1234abcd/w0\n9 ffeeddccbbaa:7:99999999/w0'
hosts=$'0a1b2c3d4e5f foslstest_worker_1\nffeeddccbbaa foslstest_worker_2'
check "the oldest running job's worker" "foslstest_worker_1 3" "$(lease_holder "${leases}" "${hosts}")"
check "a lease of another host is skipped" "foslstest_worker_2 9" \
  "$(lease_holder $'3 otherhost:1:0/w0\n9 ffeeddccbbaa:7:9/w0' "${hosts}")"
check "no running job: nobody" "1" "$(lease_holder "" "${hosts}" > /dev/null || echo $?)"
check "a running job without lease owner" "1" "$(lease_holder "4 " "${hosts}" > /dev/null || echo $?)"

{ transition 3 queued running; transition 3 running queued; } > "${scratch}/a.log"
check "put back" requeued "$(stop_outcome "${scratch}/a.log" 3)"
{ transition 3 queued running; transition 3 running succeeded; transition 5 queued running
  transition 5 running queued; } > "${scratch}/b.log"
check "finished first (and another job put back)" finished "$(stop_outcome "${scratch}/b.log" 3)"
{ echo 'not json'; transition 3 queued running; echo '{"event":"stopping"}'; } > "${scratch}/c.log"
check "still running" running "$(stop_outcome "${scratch}/c.log" 3)"
check "never there" absent "$(stop_outcome "${scratch}/c.log" 33)"
check "job 3 is not job 33" absent "$(stop_outcome "${scratch}/a.log" 33)"

# ---- the whole stop against a fake engine. Each answer of `psql` is the next line of
# leases.txt ('|' separates rows); `logs W` prints logs/W, written by `stop W` from
# stop-logs/W.N for the N-th stop of W.
fake_engine() {
  local cmd="$1"
  shift
  case "${cmd}" in
    ps) echo "fake_postgres_1" ;;
    exec)
      local n
      n=$(($(cat "${fake}/psql-calls") + 1))
      echo "${n}" > "${fake}/psql-calls"
      sed -n "${n}p" "${fake}/leases.txt" | tr '|' '\n' | sed '/^$/d'
      ;;
    inspect) echo "host-${!#}" ;;
    stop)
      local w="${!#}" n
      echo "${w}" >> "${fake}/stopped"
      n=$(grep -cx "${w}" "${fake}/stopped")
      cat "${fake}/stop-logs/${w}.${n}" >> "${fake}/logs/${w}"
      ;;
    logs) cat "${fake}/logs/${!#}" ;;
    start) echo "${!#}" >> "${fake}/started" ;;
  esac
}
engine=(fake_engine)

new_fake() {
  fake="$(mktemp -d -p "${scratch}")"
  mkdir -p "${fake}/stop-logs" "${fake}/logs"
  echo 0 > "${fake}/psql-calls"
  touch "${fake}/stopped" "${fake}/started" "${fake}/logs/w1" "${fake}/logs/w2"
}

# worker w1 idle, w2 holding job 7 (after two answers with no running job): w2 is stopped.
new_fake
printf '%s\n' "" "" "7 host-w2:12:abc/w0" > "${fake}/leases.txt"
{ transition 7 queued running; transition 7 running queued; } > "${fake}/stop-logs/w2.1"
out="$(stop_worker_holding_a_job w1 w2 && echo "victim=${victim} requeued=${requeued[*]}")"
check "the lease holder is stopped, not the idle worker" "victim=w2 requeued=7" "${out##*$'\n'}"
check "only it" "w2" "$(cat "${fake}/stopped")"

# The race the old test lost: w1's job 3 finishes before the stop lands; w1 is started again
# and the next holder, w2 with job 4, is stopped and puts it back.
new_fake
printf '%s\n' "3 host-w1:5:abc/w0" "4 host-w2:6:def/w0" > "${fake}/leases.txt"
{ transition 3 queued running; transition 3 running succeeded; } > "${fake}/stop-logs/w1.1"
{ transition 4 queued running; transition 4 running queued; } > "${fake}/stop-logs/w2.1"
out="$(stop_worker_holding_a_job w1 w2 && echo "victim=${victim} requeued=${requeued[*]}")"
check "a job that finished first is tried again" "victim=w2 requeued=4" "${out##*$'\n'}"
check "both stopped in turn" "w1 w2" "$(paste -sd' ' "${fake}/stopped")"
check "the first one started again" "w1" "$(cat "${fake}/started")"

# A stopped worker that leaves its job running fails the test, naming it.
new_fake
printf '%s\n' "5 host-w1:5:abc/w0" > "${fake}/leases.txt"
transition 5 queued running > "${fake}/stop-logs/w1.1"
if out="$( (stop_worker_holding_a_job w1 w2) 2>&1)"; then
  check "a job not put back fails" "failure" "success"
else
  check "a job not put back fails" "1" "$(grep -c 'held job 5 (its lease in the store)' <<< "${out}")"
fi

# No worker ever holds a job: fails after the wait instead of stopping an idle worker.
new_fake
: > "${fake}/leases.txt"
if out="$( (FOSLS_TEST_LEASE_WAIT=1 stop_worker_holding_a_job w1 w2) 2>&1)"; then
  check "no holder fails" "failure" "success"
else
  check "no holder fails" "1" "$(grep -c 'held a running job for 1 s' <<< "${out}")"
  check "nobody was stopped" "" "$(cat "${fake}/stopped")"
fi

((failures == 0)) || exit 1
echo "worker_stop_test: passed"
