#!/usr/bin/env python3
"""The Sedov peak-density study (issue 13, docs/sedov-peak.md): inputs/sedov2d.yaml (or sedov3d.yaml) at orders 1
and 2 on a sequence of mesh sizes, as shipped (`mesh.mesher: lattice`: 2D equilateral rows, limited by
barth_jespersen; 3D a body-centred cubic lattice of tetrahedra) and on gmsh's frontal mesh of the same quadrant
(octant) at the same mesh.size, with node_fit, whose small cells along the symmetry planes overshoot the density.
Each run records its largest cell density over every step (summary.json `largest_density`); the bound is 1.15 x the
exact peak 6 = 6.9. Prints a line per run, writes OUT_DIR/sedov_peak[3d][_cold].csv and a PNG beside it (L1 of the
density and the largest density against the cell count). --cold: pressure 0 instead of 1e-6 (a gas at rest without
sound speed); --3d: the octant.

usage: sedov_peak_study.py UNILAG OUT_DIR [SIZE ...] [--cold] [--3d]
       (default sizes 0.0577 0.0288 0.0144 0.0072, 1k to 64k triangles; 3D 0.15 0.1 0.075, 6k to 49k tetrahedra)
"""
import csv
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from script_args import fail, number, positional  # noqa: E402

SCENES = {2: os.path.join(HERE, "..", "inputs", "sedov2d.yaml"), 3: os.path.join(HERE, "..", "inputs", "sedov3d.yaml")}
SIZES = {2: [0.0577, 0.0288, 0.0144, 0.0072], 3: [0.15, 0.1, 0.075]}
BOUND = 6.9
FIELDS = ["mesh", "order", "size", "cells", "steps", "l1_density", "largest_density", "t", "x", "y", "z",
          "wall_seconds"]


MESHES = {"lattice": [], "frontal": ["--set", "mesh.mesher=gmsh", "--set", "scheme.limiter=node_fit"]}


def run(unilag, out_dir, mesh, order, size, cold, dim):
    folder = os.path.join(out_dir, f"{mesh}_o{order}_{size}")
    cmd = [unilag, "run", SCENES[dim], "--quiet", "--threads", "1", "--output", folder,
           "--set", f"scheme.order={order}", "--set", "output.interval=0", "--set", f"mesh.size={size}"] + MESHES[mesh]
    cmd += ["--set", "regions.gas.pressure=0"] if cold else []
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        fail(f"{' '.join(cmd)}: exit {done.returncode}: {done.stderr.strip()}")
    with open(os.path.join(folder, "summary.json")) as f:
        s = json.load(f)
    peak = s["largest_density"]
    return dict(mesh=mesh, order=order, size=size, cells=s["cells"], steps=s["steps"],
                l1_density=s["l1_density_error"], largest_density=peak["value"], t=peak["t"],
                x=peak["centroid"][0], y=peak["centroid"][1],
                z=peak["centroid"][2] if dim == 3 else 0.0, wall_seconds=s["wall_seconds"])


def plot(rows, png, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for mesh, style in (("lattice", "-"), ("frontal", "--")):
        for order, color in ((1, "tab:blue"), (2, "tab:red")):
            sel = [r for r in rows if r["mesh"] == mesh and r["order"] == order]
            if not sel:
                continue
            cells = [r["cells"] for r in sel]
            label = f"{mesh}, order {order}"
            ax1.loglog(cells, [r["l1_density"] for r in sel], style, marker="o", color=color, label=label)
            ax2.semilogx(cells, [r["largest_density"] for r in sel], style, marker="o", color=color, label=label)
    ax2.axhline(BOUND, color="k", lw=0.8, label="bound 6.9 (1.15 x 6)")
    ax1.set(xlabel="cells", ylabel="L1(density) at t = 1", title=f"{title}: error")
    ax2.set(xlabel="cells", ylabel="largest cell density over every step", title=f"{title}: peak")
    for ax in (ax1, ax2):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    args = positional(2, __doc__.split("\n\n")[1], most=20, flags=("--cold", "--3d"))
    cold, dim = "--cold" in sys.argv[1:], 3 if "--3d" in sys.argv[1:] else 2
    unilag, out_dir = args[0], args[1]
    sizes = [number(a, "SIZE") for a in args[2:]] or SIZES[dim]
    if not os.access(unilag, os.X_OK):
        fail(f"{unilag}: not an executable")
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    for mesh in MESHES:
        for order in (1, 2):
            for size in sizes:
                r = run(unilag, out_dir, mesh, order, size, cold, dim)
                rows.append(r)
                print(f"{mesh:8s} order {order} {r['cells']:7d} cells {r['steps']:5d} steps  L1 {r['l1_density']:.5f}"
                      f"  largest {r['largest_density']:.3f} at t {r['t']:.3f} ({r['x']:.4f}, {r['y']:.4f})"
                      f"{'  > 6.9' if r['largest_density'] > BOUND else ''}", flush=True)
    name = f"sedov_peak{'3d' if dim == 3 else ''}{'_cold' if cold else ''}"
    csv_path = os.path.join(out_dir, name + ".csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    plot(rows, csv_path.replace(".csv", ".png"), f"{dim}D Sedov{' (p = 0)' if cold else ''}")
    print(f"wrote {csv_path} and a PNG beside it")


if __name__ == "__main__":
    main()
