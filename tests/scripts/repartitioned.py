#!/usr/bin/env python3
"""Assert that runs repartitioned as forced (parallel.imbalance_threshold 0): summary.json's load_balance has a
repartition at every check, every INTERVAL steps before the last, and on 2+ ranks cells moved (otherwise a bitwise comparison with
an unpartitioned run would prove nothing).

usage: repartitioned.py INTERVAL RUN_DIR [RUN_DIR ...]
"""
import json
import os
import sys


def check(interval, run):
    try:
        with open(os.path.join(run, "summary.json")) as f:
            s = json.load(f)
    except (OSError, ValueError) as e:
        return f"{run}: cannot read summary.json: {e}"
    lb = s.get("load_balance")
    if lb is None:
        return f"{run}: no load_balance in summary.json"
    events = lb["repartitions"]
    expected = (s["steps"] - 1) // interval  # none after the last step
    if len(events) != expected or lb["checks"] != expected:
        return f"{run}: {len(events)} repartitions in {lb['checks']} checks, expected {expected} ({s['steps']} steps)"
    if [e["step"] for e in events] != [interval * (k + 1) for k in range(expected)]:
        return f"{run}: repartitions at steps {[e['step'] for e in events]}"
    moved = sum(e["cells_moved"] for e in events)
    if s["ranks"] > 1 and moved == 0:
        return f"{run}: no cell moved in {len(events)} repartitions on {s['ranks']} ranks"
    print(f"repartitioned: {run}: {len(events)} repartitions on {s['ranks']} rank(s), {moved} cell moves")
    return ""


def main():
    interval = int(sys.argv[1])
    errors = [e for e in (check(interval, run) for run in sys.argv[2:]) if e]
    for e in errors:
        print("repartitioned: FAIL, " + e)
    return 1 if errors or len(sys.argv) < 3 else 0


if __name__ == "__main__":
    sys.exit(main())
