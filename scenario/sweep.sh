#!/usr/bin/env bash
# Runs ./warehouse-scenario once per seed with the same options and prints a table from each run's report.json:
# carts per warehouse hour, the share of the smaller bound (doors alternating, or the fleet's own), the longest wait
# behind a robot, the share of robot time spent waiting, deadlocks, verdict; then the median and minimum share.
# A benchmark, not a test (each 30-robot run takes 1-3 minutes of wall time). Needs python3 for the table.
#
#   scenario/sweep.sh "1 2 3 4" --generate --traffic --speed 5
#   scenario/sweep.sh "1 2 3" --generate --width 120 --height 40 --robots 60 --carts 120 --traffic --speed 5
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ $# -lt 1 ]; then
  echo "usage: scenario/sweep.sh \"SEEDS\" [warehouse-scenario options]" >&2
  exit 2
fi
seeds="$1"; shift
dir="$root/scenario/target/sweeps/$(date +%Y%m%d-%H%M%S)"
mkdir -p "$dir"
for seed in $seeds; do
  "$root/warehouse-scenario" "$@" --seed "$seed" --report "$dir/seed-$seed.json" --progress 60 > "$dir/seed-$seed.log" 2>&1
  echo "seed $seed: exit $? ($(tail -1 "$dir/seed-$seed.log" | cut -c1-100))" >&2
done
python3 - "$dir" "$*" <<'PY'
import json, glob, os, sys, statistics
rows, shares = [], []
for f in sorted(glob.glob(os.path.join(sys.argv[1], "seed-*.json")), key=lambda p: int(p.split("-")[-1][:-5])):
    r = json.load(open(f)); g = r["figures"]
    cph = g.get("cartsPerWarehouseHour") or 0
    bound = min(g["doorBoundCartsPerWarehouseHour"], g.get("fleetBoundCartsPerWarehouseHour") or 1e18)
    share = cph / bound if bound else 0
    shares.append(share)
    rows.append((r["warehouse"]["seed"], cph, g["doorBoundCartsPerWarehouseHour"],
                 g.get("fleetBoundCartsPerWarehouseHour") or 0, share, g["waitMaxMs"] / 1000, g["waitShare"],
                 g["deadlocks"], g.get("goTosSent"), g.get("goTosAlongReservedPaths"), "PASS" if r["passed"] else "FAIL"))
print("options:", sys.argv[2])
print("| seed | carts/h | door bound | fleet bound | share of bound | longest wait | waiting | deadlocks | go-tos | reserved | verdict |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for s in rows:
    print("| %d | %.0f | %.0f | %.0f | %.0f%% | %.1f s | %.1f%% | %d | %s | %s | %s |" % (s[0], s[1], s[2], s[3], 100 * s[4], s[5], 100 * s[6], s[7], s[8], s[9], s[10]))
if shares:
    print("share of bound: median %.0f%%, minimum %.0f%% over %d seeds" % (100 * statistics.median(shares), 100 * min(shares), len(shares)))
PY
