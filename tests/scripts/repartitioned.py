#!/usr/bin/env python3
"""Assert that runs repartitioned as forced (parallel.imbalance_threshold 0): summary.json's load_balance has a
repartition at every check, every INTERVAL steps (parallel.check_interval) and every EARLY steps
(parallel.early_check_interval) through the first INTERVAL steps, none at the last step, and on 2+ ranks cells moved
(otherwise a bitwise comparison with an unpartitioned run would prove nothing).

usage: repartitioned.py INTERVAL EARLY RUN_DIR [RUN_DIR ...]
"""
import json
import os
import sys


def check(interval, early, run):
    try:
        with open(os.path.join(run, "summary.json")) as f:
            s = json.load(f)
    except (OSError, ValueError) as e:
        return f"{run}: cannot read summary.json: {e}"
    lb = s.get("load_balance")
    if lb is None:
        return f"{run}: no load_balance in summary.json"
    events = lb["repartitions"]
    steps = [k for k in range(1, s["steps"]) if k % interval == 0 or (k < interval and k % early == 0)]
    if len(events) != len(steps) or lb["checks"] != len(steps):
        return f"{run}: {len(events)} repartitions in {lb['checks']} checks, expected {len(steps)} ({s['steps']} steps)"
    if [e["step"] for e in events] != steps:
        return f"{run}: repartitions at steps {[e['step'] for e in events]}, expected {steps}"
    moved = sum(e["cells_moved"] for e in events)
    if s["ranks"] > 1 and moved == 0:
        return f"{run}: no cell moved in {len(events)} repartitions on {s['ranks']} ranks"
    print(f"repartitioned: {run}: {len(events)} repartitions on {s['ranks']} rank(s), {moved} cell moves")
    return ""


def main():
    interval, early = int(sys.argv[1]), int(sys.argv[2])
    errors = [e for e in (check(interval, early, run) for run in sys.argv[3:]) if e]
    for e in errors:
        print("repartitioned: FAIL, " + e)
    return 1 if errors or len(sys.argv) < 4 else 0


if __name__ == "__main__":
    sys.exit(main())
