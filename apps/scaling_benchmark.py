#!/usr/bin/env python3
"""Thread and rank scaling of one scene, by alternating runs (issue 14 item 3, docs/parallel.md 6): each round runs
the scene on 1 thread, on 2 threads (one rank) and on 2 ranks (one thread each), back to back, and right before
them a machine probe: a compute-only loop timed alone and then as two processes at once, whose speed-up
(2 x alone / both) is what the machine's two cores deliver in that window (2.0 on a quiet machine; less where the
second core is shared with someone else). Prints each round's wall times and speed-ups over 1 thread, then the
medians; writes every round as CSV and a PNG of the speed-ups against the probe's beside it.

usage: scaling_benchmark.py OUT.csv ROUNDS SCENE [--set key=value ...]
  e.g. apps/scaling_benchmark.py out/sedov64k_o1.csv 3 inputs/sedov2d.yaml --set mesh.size=0.0072 \\
         --set time.end=0.5
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from multiprocessing import Process

import study_plot

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UNILAG = os.path.join(ROOT, "build", "release", "apps", "unilag")
PROBE_ITERATIONS = 6_000_000


def spin():
    x = 0
    for i in range(PROBE_ITERATIONS):
        x += i * i
    return x


def timed_processes(n):
    procs = [Process(target=spin) for _ in range(n)]
    t0 = time.perf_counter()
    for p in procs:
        p.start()
    for p in procs:
        p.join()
    return time.perf_counter() - t0


def probe():
    """The machine's two-core speed-up now: one compute-only process alone, then two at once, medians of 3 (fresh
    processes each time: a loop the parent has run before runs faster in it)."""
    alone = statistics.median(timed_processes(1) for _ in range(3))
    both = statistics.median(timed_processes(2) for _ in range(3))
    return 2.0 * alone / both


def run(scene_args, ranks, threads):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with tempfile.TemporaryDirectory() as out:
        cmd = [UNILAG, "run", *scene_args, "--quiet", "--set", "output.enabled=false", "--set",
               "parallel.repartition=false", "--output", out]
        if ranks > 1:
            cmd = ["mpirun", "--oversubscribe", "-np", str(ranks), "-x", "OMP_NUM_THREADS"] + cmd
        subprocess.run(cmd, env=env, check=True, stdout=subprocess.DEVNULL)
        s = json.load(open(os.path.join(out, "summary.json")))
    return s["wall_seconds"], s["steps"], s["cells"]


def plot(png, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5.5, 3.5))
    probe_ = [r["machine_speedup"] for r in rows]
    ax.plot(probe_, [r["speedup_2_threads"] for r in rows], "o", label="2 threads")
    ax.plot(probe_, [r["speedup_2_ranks"] for r in rows], "s", label="2 ranks")
    lo = min(probe_ + [1.5])
    ax.plot([lo, 2.05], [lo, 2.05], "k:", lw=0.8, label="= the machine's")
    study_plot.finish(fig, ax, png, "machine probe: two-core speed-up in the same round", "speed-up over 1 thread", 1.8)


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    out_csv, rounds, scene_args = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    rows = []
    for k in range(rounds):
        machine = probe()
        one, steps, cells = run(scene_args, 1, 1)
        two_threads, _, _ = run(scene_args, 1, 2)
        two_ranks, _, _ = run(scene_args, 2, 1)
        row = {"round": k, "cells": cells, "steps": steps, "machine_speedup": machine, "wall_1_thread": one,
               "wall_2_threads": two_threads, "wall_2_ranks": two_ranks, "speedup_2_threads": one / two_threads,
               "speedup_2_ranks": one / two_ranks}
        rows.append(row)
        print(f"round {k}: machine {machine:.2f}x  1 thread {one:.2f} s  2 threads {two_threads:.2f} s "
              f"({row['speedup_2_threads']:.2f}x)  2 ranks {two_ranks:.2f} s ({row['speedup_2_ranks']:.2f}x)",
              flush=True)
    med = {key: statistics.median(r[key] for r in rows) for key in rows[0] if key != "round"}
    print(f"median: machine {med['machine_speedup']:.2f}x  2 threads {med['speedup_2_threads']:.2f}x  "
          f"2 ranks {med['speedup_2_ranks']:.2f}x ({rows[0]['cells']} cells, {rows[0]['steps']} steps)")
    os.makedirs(os.path.dirname(os.path.abspath(out_csv)), exist_ok=True)
    with open(out_csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    plot(os.path.splitext(out_csv)[0] + ".png", rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
