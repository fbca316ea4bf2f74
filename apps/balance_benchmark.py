#!/usr/bin/env python3
"""Repartitioning against none, by alternating runs (A B A B ...) of one scene on NP ranks: A with
parallel.repartition false (measured only), B with the scene's load balance. Prints, per run, the wall time and the
imbalance (max / mean of the ranks' busy times per check: mean, max, last), the cost model's imbalance and the
ranks' speed spread (summary.json load_balance) with B's repartitions, then the medians
and the median of the pairs' wall-time ratios B / A; writes every run as CSV, every check of every run (measured
and model imbalance, repartitions) as OUT_checks.csv, and a PNG of the imbalance through the runs beside them.

usage: balance_benchmark.py OUT.csv NP ROUNDS SCENE [--set key=value ...]
  e.g. apps/balance_benchmark.py out/impact.csv 2 3 inputs/impact2d.yaml --set mesh.size=0.0005
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile

import study_plot

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UNILAG = os.path.join(ROOT, "build", "release", "apps", "unilag")


def run(np_, scene_args, repartition, out):
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    cmd = ["mpirun", "--oversubscribe", "-np", str(np_), UNILAG, "run", *scene_args, "--quiet", "--set",
           "output.interval=0", "--set", f"parallel.repartition={'true' if repartition else 'false'}",
           "--output", out]
    subprocess.run(cmd, env=env, check=True, stdout=subprocess.DEVNULL)
    s = json.load(open(os.path.join(out, "summary.json")))
    lb = s.get("load_balance", {"imbalance_mean": 1.0, "imbalance_max": 1.0, "imbalance_last": 1.0,
                                "model_imbalance_mean": 1.0, "speed_spread_mean": 0.0, "repartitions": []})
    rows = list(csv.DictReader(open(os.path.join(out, "balance.csv")))) if "load_balance" in s else []
    return {"repartition": repartition, "wall_seconds": s["wall_seconds"], "steps": s["steps"],
            "imbalance_mean": lb["imbalance_mean"], "imbalance_max": lb["imbalance_max"],
            "imbalance_last": lb["imbalance_last"], "model_imbalance_mean": lb["model_imbalance_mean"],
            "speed_spread_mean": lb.get("speed_spread_mean", 0.0), "repartitions": len(lb["repartitions"]),
            "cells_moved": sum(e["cells_moved"] for e in lb["repartitions"]),
            "repartition_seconds": sum(e["seconds"] for e in lb["repartitions"])}, rows


def plot(png, checks):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 3.5))
    for k in sorted({c["round"] for c in checks}):
        for flag, colour, label in ((False, "C0", "without repartitioning"), (True, "C1", "with")):
            rows = [c for c in checks if c["round"] == k and c["repartition"] == flag]
            ax.plot([int(r["step"]) for r in rows], [float(r["imbalance"]) for r in rows], "o-", color=colour,
                    label=label if k == 0 else None, alpha=0.8)
            if flag:
                ax.plot([int(r["step"]) for r in rows], [float(r["model_imbalance"]) for r in rows], ":",
                        color=colour, label="with: the model's imbalance" if k == 0 else None, alpha=0.8)
            moved = [r for r in rows if r["repartitioned"] == "1"]
            ax.plot([int(r["step"]) for r in moved], [float(r["imbalance"]) for r in moved], "kx",
                    label="repartition" if k == 0 and flag else None)
    study_plot.finish(fig, ax, png, "step", "imbalance (max / mean busy time)", 1.15)


def main():
    if len(sys.argv) < 5:
        print(__doc__)
        return 2
    out_csv, np_, rounds, scene_args = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4:]
    results, ratios, checks = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(rounds):
            a, rows_a = run(np_, scene_args, False, os.path.join(tmp, f"a{k}"))
            b, rows_b = run(np_, scene_args, True, os.path.join(tmp, f"b{k}"))
            for label, r in (("A none", a), ("B repartition", b)):
                print(f"round {k} {label:14s} wall {r['wall_seconds']:.3f} s  imbalance mean {r['imbalance_mean']:.3f}"
                      f" max {r['imbalance_max']:.3f} last {r['imbalance_last']:.3f}  model mean "
                      f"{r['model_imbalance_mean']:.3f} speed spread mean {r['speed_spread_mean']:.3f}  repartitions "
                      f"{r['repartitions']} ({r['cells_moved']} cells, {r['repartition_seconds']:.3f} s)")
                results.append(dict(r, round=k))
            ratios.append(b["wall_seconds"] / a["wall_seconds"])
            for flag, rows in ((False, rows_a), (True, rows_b)):
                checks += [dict(row, round=k, repartition=flag) for row in rows]
    for flag, label in ((False, "A none"), (True, "B repartition")):
        rs = [r for r in results if r["repartition"] == flag]
        print(f"median {label:14s} wall {statistics.median(r['wall_seconds'] for r in rs):.3f} s  imbalance mean "
              f"{statistics.median(r['imbalance_mean'] for r in rs):.3f} max "
              f"{statistics.median(r['imbalance_max'] for r in rs):.3f} model mean "
              f"{statistics.median(r['model_imbalance_mean'] for r in rs):.3f} speed spread mean "
              f"{statistics.median(r['speed_spread_mean'] for r in rs):.3f}")
    print(f"median wall ratio B / A: {statistics.median(ratios):.3f} over {rounds} pairs")
    os.makedirs(os.path.dirname(os.path.abspath(out_csv)), exist_ok=True)
    with open(out_csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        w.writeheader()
        w.writerows(results)
    stem = os.path.splitext(out_csv)[0]
    if checks:
        with open(stem + "_checks.csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(checks[0].keys()))
            w.writeheader()
            w.writerows(checks)
        plot(stem + ".png", checks)
    return 0


if __name__ == "__main__":
    sys.exit(main())
