#!/usr/bin/env python3
"""One BENCHMARKS.md table row per report.json of ./warehouse-scenario: the run's arguments (a --node-config file
by its name only), passed (or the failed checks), wall time, warehouse time until every cart was delivered (and of
the whole run), carts per warehouse hour against the door's alternating bound, share of robot time waiting behind
another robot, robot-in-front detections with the median and longest wait, deadlocks, bus events per second, node CPU.

Usage: scenario/report-rows.py scenario/target/runs/*/report.json
"""
import json
import os
import sys


def arguments(args):
    shown = []
    for i, a in enumerate(args):
        if i > 0 and args[i - 1] == "--node-config":
            shown.append(os.path.basename(a))
        elif a not in ("--progress",) and not (i > 0 and args[i - 1] == "--progress"):
            shown.append(a)
    return " ".join(shown)


for path in sys.argv[1:]:
    with open(path) as file:
        r = json.load(file)
    f = r["figures"]
    fails = [c["detail"] for c in r["checks"] if not c["passed"]]
    until = f.get("warehouseSecondsUntilAllDelivered")
    per_hour = f.get("cartsPerWarehouseHour") or 0
    bound = f.get("doorBoundCartsPerWarehouseHour") or 0
    share = f"{100 * per_hour / bound:.0f}% of {bound:.0f}" if bound else "no bound"
    print(f"| `{arguments(r['arguments'])}` | {'yes' if r['passed'] else 'no: ' + '; '.join(fails)[:110]} "
          f"| {f['wallSeconds']:.1f} | {until if until is not None else 'never'} ({f['warehouseSeconds']}) "
          f"| {per_hour:.0f} ({share}) | {100 * f['waitShare']:.1f}% "
          f"| {f['robotInFrontDetections']}: {f['waitMedianMs'] / 1000:.1f}, {f['waitMaxMs'] / 1000:.1f} "
          f"| {f['deadlocks']} | {f['busEventsPerSecond']:.0f} "
          f"| {f['nodeCpuSeconds']:.1f} ({f['nodeCpuPercentOfOneCore']:.0f}%) |")
