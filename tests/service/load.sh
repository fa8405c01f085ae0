#!/usr/bin/env bash
# GET latency of fosls-serve while both workers solve. Starts its own server on a free
# loopback port with a temporary database, keeps two long solves running, measures, then
# cancels them and stops the server (also on failure or Ctrl-C).
#
#   tests/service/load.sh [BUILD_DIR] [SECONDS]     # defaults: build, 10
#
# Uses wrk when installed, else a curl loop (sequential requests, so fewer of them).
set -euo pipefail

build_dir=${1:-build}
seconds=${2:-10}
serve="$build_dir/bin/fosls-serve"
[ -x "$serve" ] || { echo "no $serve; build first" >&2; exit 1; }

tmp=$(mktemp -d)
server_pid=""
cleanup() {
  if [ -n "$server_pid" ] && kill -0 "$server_pid" 2>/dev/null; then
    kill -TERM "$server_pid" 2>/dev/null || true
    for _ in $(seq 1 300); do kill -0 "$server_pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$server_pid" 2>/dev/null || true
  fi
  rm -rf "$tmp"
}
trap cleanup EXIT INT TERM

"$serve" --host 127.0.0.1 --port 0 --workers 2 --db "$tmp/jobs.db" --web-root "$tmp" \
  >"$tmp/stdout" 2>"$tmp/server.log" &
server_pid=$!
port=""
for _ in $(seq 1 300); do
  port=$(sed -n 's|^listening on http://127.0.0.1:\([0-9]*\)$|\1|p' "$tmp/stdout")
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { echo "server did not start:" >&2; cat "$tmp/server.log" >&2; exit 1; }
base="http://127.0.0.1:$port"

# Projected Gauss-Seidel on a fine mesh with an unreachable tolerance keeps a worker busy.
long_case='{"name":"load","mesh":{"builtin":"square","size":0.25,"refinements":5},
 "material":{"mu":1,"lambda":1},
 "boundary":{"top":{"type":"dirichlet","displacement":[0,-0.05]},
  "bottom":{"type":"contact","obstacle":{"type":"gap","g":"0.4*(x-0.5)^2"}}},
 "solver":{"method":"pgs","tolerance":1e-15,"max_iterations":100000}}'
ids=()
for _ in 1 2; do
  location=$(curl -sS -o /dev/null -w '%header{location}' \
    -H 'Content-Type: application/json' --data-binary "$long_case" "$base/v1/jobs")
  ids+=("${location##*/}")
done
for _ in $(seq 1 600); do
  curl -sS "$base/metrics" | grep -q '^fosls_workers_busy 2$' && break
  sleep 0.1
done
curl -sS "$base/metrics" | grep -q '^fosls_workers_busy 2$' ||
  { echo "workers did not start solving" >&2; exit 1; }

echo "machine: $(nproc) cores, $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)"
echo "while 2 workers solve (jobs ${ids[*]}), ${seconds}s per endpoint:"
targets=("/v1/jobs/${ids[0]}" "/v1/jobs?page_size=20" "/healthz")
if command -v wrk >/dev/null; then
  run_wrk() {  # threads connections path
    echo "== GET $3 (wrk -t$1 -c$2)"
    timeout $((seconds + 30)) wrk -t"$1" -c"$2" -d"${seconds}s" --latency "$base$3" |
      grep -E '^ +(50|90|99)%|Requests/sec|Non-2xx|Socket errors'
  }
  run_wrk 1 1 "${targets[0]}"  # one client polling back to back
  for t in "${targets[@]}"; do run_wrk 2 8 "$t"; done
else
  for t in "${targets[@]}"; do
    echo "== GET $t (sequential curl)"
    end=$((SECONDS + seconds))
    : >"$tmp/times"
    while [ $SECONDS -lt $end ]; do
      curl -sS -o /dev/null -w '%{time_total}\n' "$base$t" >>"$tmp/times"
    done
    sort -n "$tmp/times" | awk '{a[NR]=$1} END {
      printf "requests %d  p50 %.2f ms  p90 %.2f ms  p99 %.2f ms  max %.2f ms\n", NR,
        1000*a[int(NR*0.5)+1], 1000*a[int(NR*0.9)+1], 1000*a[int(NR*0.99)+1], 1000*a[NR] }'
  done
fi
progress=$(curl -sS "$base/v1/jobs/${ids[0]}")
echo "job ${ids[0]} after the run: ${progress}"
for id in "${ids[@]}"; do curl -sS -o /dev/null -X POST "$base/v1/jobs/$id/cancel"; done
if grep -q 'database is locked' "$tmp/server.log"; then
  echo "FAIL: 'database is locked' in the server log" >&2
  exit 1
fi
