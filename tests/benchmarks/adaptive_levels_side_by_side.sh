#!/usr/bin/env bash
# adaptive_levels_side_by_side.sh BASE_BIN NEW_BIN [DIR]
# The table of docs/performance.md "The contact zone's levels skipped too": the 2D Hertz cases
# (λ = 1 and ∞) to a force accuracy of 5e-4 from refinements 2 with mmg, uniform levels (BASE_BIN)
# and adaptive levels (BASE_BIN, then NEW_BIN), two rounds; then hertz_3d_accuracy with mmg
# (BASE_BIN, NEW_BIN), one round. One thread, /usr/bin/time -v: CPU time = user + sys.
set -eu
BASE=$1 NEW=$2 DIR=${3:-$(mktemp -d)}
cd "$DIR"
export OMP_NUM_THREADS=1
for c in hertz hertz_incompressible; do
  for r in uniform adaptive; do
    "$NEW" example $c | python3 -c "
import json, sys
d = json.load(sys.stdin)
d['mesh']['refinements'] = 2
d['accuracy'] = {'force': 5e-4, 'refinement': '$r'}
d['solver'] = {'method': 'mmg'}
json.dump(d, open('acc_${c}_$r.json', 'w'))"
  done
done
"$NEW" example hertz_3d_accuracy | python3 -c "
import json, sys
d = json.load(sys.stdin); d['solver'] = {'method': 'mmg'}; json.dump(d, open('hertz_3d_mmg.json', 'w'))"
run() {  # label binary case
  /usr/bin/time -v "$2" solve "$3.json" --out "res_$1_$3.json" -q 2> "time_$1_$3.txt" >/dev/null || true
  python3 - "$1" "$3" <<'PY'
import json, re, sys
label, case = sys.argv[1:]
t = open(f"time_{label}_{case}.txt").read()
cpu = sum(float(re.search(k + r" \(seconds\): ([0-9.]+)", t).group(1)) for k in ("User time", "System time"))
rss = int(re.search(r"Maximum resident set size \(kbytes\): ([0-9]+)", t).group(1))
d = json.load(open(f"res_{label}_{case}.json"))
a = d.get("accuracy", {})
steps = a.get("steps", [])
print(f"{label:5s} {case:34s} cpu {cpu:7.2f} peak {rss / 1024:6.0f} MiB solves {len(steps)} last {d['dofs']} "
      f"reached {a.get('reached')} estimate {a.get('estimate')} iterations {[s['iterations'] for s in steps]} "
      f"force {d['contact'].get('force')}", flush=True)
PY
}
uptime
for round in 1 2; do
  for c in hertz hertz_incompressible; do
    run base "$BASE" acc_${c}_uniform
    run base "$BASE" acc_${c}_adaptive
    run new "$NEW" acc_${c}_adaptive
  done
done
run base "$BASE" hertz_3d_mmg
run new "$NEW" hertz_3d_mmg
uptime
