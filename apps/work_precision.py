#!/usr/bin/env python3
"""Work against error for any scene: an error measure from summary.json against wall time, order 1 and order 2.

Runs SCENE with scheme.order = 1 and 2 at each mesh size, reads MEASURE from each run's summary.json, and prints per
run the cells, steps, wall time, cell-steps per second and the error; writes WORKDIR/work_precision.csv and
WORKDIR/work_precision.png (error against wall time, both orders; the point where order 2 reaches order 1's finest
error is what "second order pays" means). A benchmark, not a test: it prints figures and asserts nothing.

MEASURE is a dotted path into summary.json:
  l1_density_error                  L1(density) against the exact profile (Sedov)
  l2_error.velocity                 the vortex's L2 errors (also l2_error.specific_volume, l2_error.energy)
  boundary_mean_radius.inner=0.05   a boundary's mean radius: with =EXACT, the error is |value - EXACT| / EXACT
  script:apps/plate_period.py=28.89e-6   a script run on each run's output folder (the scene's own output kept):
                                    the number on its last line, here the Be plate's period against 28.89 us

usage: work_precision.py UNILAG SCENE MEASURE WORKDIR SIZE[,SIZE...] [--set KEY=VALUE ...]
examples (one core):
  OMP_NUM_THREADS=1 apps/work_precision.py build/release/apps/unilag inputs/vortex2d.yaml l2_error.velocity \\
      /tmp/wp 0.4,0.3,0.2,0.15
  OMP_NUM_THREADS=1 apps/work_precision.py build/release/apps/unilag inputs/be_shell2d.yaml \\
      boundary_mean_radius.inner=0.05 /tmp/wp 0.0014,0.001,0.0007
  OMP_NUM_THREADS=1 apps/work_precision.py build/release/apps/unilag inputs/be_plate2d.yaml \\
      script:apps/plate_period.py=28.89e-6 /tmp/wp 0.001,0.0007,0.0005 --set mesh.geometry=geometry/plate_half2d.geo \\
      --set boundaries.left.type=symmetry
"""
import csv
import json
import os
import subprocess
import sys


def parse_measure(text):
    """(keys into summary.json, or ["script:", PATH]; the exact value or None)."""
    path, _, exact = text.partition("=")
    keys = ["script:", path[len("script:"):]] if path.startswith("script:") else path.split(".")
    return keys, (float(exact) if exact else None)


def measure(summary, path, exact, out):
    if path[0] == "script:": # the number on the last line the script prints for the output folder
        lines = subprocess.run([sys.executable, path[1], out], check=True, capture_output=True, text=True).stdout
        value = float(lines.strip().splitlines()[-1])
        return abs(value - exact) / abs(exact) if exact is not None else value
    value = summary
    for key in path:
        if key not in value:
            sys.exit(f"work_precision.py: summary.json has no '{'.'.join(path)}' (at '{key}')")
        value = value[key]
    value = float(value)
    return abs(value - exact) / abs(exact) if exact is not None else value


def run(unilag, scene, out, order, size, extra, keep_output):
    output = [] if keep_output else ["--set", "output.enabled=false"]
    subprocess.run([unilag, "run", scene, "--quiet", "--set", f"scheme.order={order}", "--set", f"mesh.size={size}",
                    "--output", out] + output + extra, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def plot(rows, label, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4.5))
    for order, marker in ((1, "o"), (2, "s")):
        mine = [r for r in rows if r["order"] == order]
        ax.loglog([r["wall_seconds"] for r in mine], [r["error"] for r in mine], marker + "-", label=f"order {order}")
        for r in mine:
            ax.annotate(str(r["cells"]), (r["wall_seconds"], r["error"]), fontsize=6, alpha=0.6)
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel(label)
    ax.legend(fontsize=8)
    ax.set_title("work against error (labels: cells)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    if len(sys.argv) < 6:
        sys.exit(__doc__)
    unilag, scene, measure_text, work, sizes = sys.argv[1:6]
    extra = sys.argv[6:]
    path, exact = parse_measure(measure_text)
    scene = os.path.abspath(scene)
    os.makedirs(work, exist_ok=True)
    rows = []
    print(f"{'order':>5} {'size':>8} {'cells':>7} {'steps':>7} {'wall s':>8} {'cell-steps/s':>13} {'error':>10}")
    for order in (1, 2):
        for size in sizes.split(","):
            out = os.path.join(work, f"o{order}_h{size}")
            s = run(unilag, scene, out, order, size, extra, path[0] == "script:")
            row = {"order": order, "size": float(size), "cells": s["cells"], "steps": s["steps"],
                   "wall_seconds": s["wall_seconds"], "cell_steps_per_second": s["cell_steps_per_second"],
                   "error": measure(s, path, exact, out)}
            rows.append(row)
            print(f"{order:>5} {size:>8} {row['cells']:>7} {row['steps']:>7} {row['wall_seconds']:>8.2f} "
                  f"{row['cell_steps_per_second']:>13.3g} {row['error']:>10.4g}", flush=True)
    with open(os.path.join(work, "work_precision.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    label = measure_text if exact is None else f"relative error of {measure_text.partition('=')[0]}"
    plot(rows, label, os.path.join(work, "work_precision.png"))
    print(f"wrote {work}/work_precision.csv and .png")


if __name__ == "__main__":
    main()
