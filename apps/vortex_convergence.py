#!/usr/bin/env python3
"""The isentropic vortex's convergence table in the paper's format (docs/gpr-model.md 3.1).

Runs SCENE (inputs/vortex2d.yaml, or vortex3d.yaml: the paper's 3D table) at each mesh size, order 1 and order 2, reads summary.json's l2_error and prints,
per order, h on the final mesh, the L2 errors of the specific volume, the velocity and the total energy, and the
observed orders between consecutive meshes, next to the paper's table, and the mesh's geometric floor of the specific
volume and energy errors (vortex_floor.py: the same cells moved exactly); writes WORKDIR/vortex_convergence.csv and
WORKDIR/vortex_convergence.png (error against h, the paper's points as open markers, the floor dashed).

usage: vortex_convergence.py UNILAG SCENE WORKDIR [SIZE,SIZE,...] [--set KEY=VALUE ...]
  e.g. --set mesh.geometry=geometry/vortex_square2d_structured.geo for the structured 2D mesh.
"""
import csv
import json
import math
import os
import subprocess
import sys

from vortex_floor import floor

# The paper's tables (h, omega, u, E), gpr.md 3.1, for comparison at equal h: 2D, and 3D (the vortex extruded).
PAPER_2D = {
    1: [(3.26e-1, 5.405e-2, 1.547e-1, 2.579e-1), (2.47e-1, 4.164e-2, 1.219e-1, 2.044e-1),
        (1.63e-1, 3.053e-2, 8.866e-2, 1.471e-1), (1.28e-1, 2.286e-2, 7.041e-2, 1.164e-1)],
    2: [(3.26e-1, 4.996e-2, 4.895e-2, 9.281e-2), (2.47e-1, 3.312e-2, 3.020e-2, 5.509e-2),
        (1.63e-1, 1.913e-2, 1.534e-2, 2.858e-2), (1.28e-1, 1.327e-2, 9.153e-3, 1.770e-2)],
}
PAPER_3D = {
    1: [(5.29e-1, 2.389e-1, 5.600e-1, 8.781e-1), (3.62e-1, 2.013e-1, 4.075e-1, 6.660e-1),
        (2.31e-1, 1.752e-1, 2.882e-1, 4.877e-1), (1.81e-1, 1.454e-1, 2.301e-1, 3.974e-1)],
    2: [(5.29e-1, 2.899e-1, 2.946e-1, 5.185e-1), (3.62e-1, 1.426e-1, 1.188e-1, 2.275e-1),
        (2.31e-1, 8.304e-2, 5.829e-2, 1.099e-1), (1.81e-1, 5.931e-2, 3.600e-2, 7.206e-2)],
}
PAPER = {2: PAPER_2D, 3: PAPER_3D}
FIELDS = ("specific_volume", "velocity", "energy")


def run(unilag, scene, work, order, size, extra):
    out = os.path.join(work, f"o{order}_h{size}")
    cmd = [unilag, "run", scene, "--quiet", "--output", out, "--set", f"scheme.order={order}", "--set",
           f"mesh.size={size}", "--set", "output.interval=1e30"] + extra # dumps at t = 0 and the end only
    subprocess.run(cmd, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    l2 = summary["l2_error"]
    floor_omega, floor_energy = floor(os.path.join(out, "unilag_000000.h5"), summary["t_final"])
    return {"order": order, "size": float(size), "dimension": summary["dimension"], "cells": summary.get("cells", 0),
            "h": l2["h_final"],
            "wall_seconds": summary["wall_seconds"], **{k: l2[k] for k in FIELDS},
            "floor_specific_volume": floor_omega, "floor_energy": floor_energy}


def observed(rows, k, i):
    if i == 0:
        return float("nan")
    return math.log(rows[i - 1][k] / rows[i][k]) / math.log(rows[i - 1]["h"] / rows[i]["h"])


def print_table(order, rows):
    print(f"\norder {order}: {'h':>9} {'omega L2':>10} {'O':>5} {'u L2':>10} {'O':>5} {'E L2':>10} {'O':>5}"
          f" {'cells':>7} {'wall s':>7}   floor: {'omega':>9} {'E':>9}")
    for i, r in enumerate(rows):
        line = f"         {r['h']:9.3e}"
        for k in FIELDS:
            line += f" {r[k]:10.3e} {observed(rows, k, i):5.2f}"
        print(line + f" {r['cells']:7d} {r['wall_seconds']:7.2f}          {r['floor_specific_volume']:9.3e}"
                     f" {r['floor_energy']:9.3e}")
    paper = PAPER[rows[0]["dimension"]][order]
    print("  paper:  " + "   ".join(f"h {h:.2e}: {w:.3e} {u:.3e} {e:.3e}" for h, w, u, e in paper))


def plot(rows, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8))
    for ax, k, col in zip(axes, FIELDS, (1, 2, 3)):
        for order, marker in ((1, "o"), (2, "s")):
            mine = [r for r in rows if r["order"] == order]
            ax.loglog([r["h"] for r in mine], [r[k] for r in mine], marker + "-", label=f"unilag order {order}")
            paper = PAPER[rows[0]["dimension"]][order]
            ax.loglog([p[0] for p in paper], [p[col] for p in paper], marker, mfc="none", color="grey",
                      label=f"paper order {order}")
        if k != "velocity":
            mine = [r for r in rows if r["order"] == 2]
            ax.loglog([r["h"] for r in mine], [r["floor_" + k] for r in mine], "k--", lw=0.8,
                      label="geometric floor (exact node paths)")
        ax.set_xlabel("h on the final mesh")
        ax.set_ylabel(f"L2 error of the {k.replace('_', ' ')}")
        ax.set_title(f"L2 error, {k.replace('_', ' ')}", fontsize=9)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    unilag, scene, work = sys.argv[1:4]
    sizes = sys.argv[4].split(",") if len(sys.argv) > 4 and not sys.argv[4].startswith("--") else \
        ["0.4", "0.3", "0.2", "0.15"]
    extra = [a for a in sys.argv[4:] if a.startswith("--") or "=" in a]
    os.makedirs(work, exist_ok=True)
    scene = os.path.abspath(scene)
    rows = []
    for order in (1, 2):
        mine = [run(unilag, scene, work, order, s, extra) for s in sizes]
        print_table(order, mine)
        rows += mine
    with open(os.path.join(work, "vortex_convergence.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(work, "vortex_convergence.png"))
    print(f"\nwrote {work}/vortex_convergence.csv and .png")


if __name__ == "__main__":
    main()
