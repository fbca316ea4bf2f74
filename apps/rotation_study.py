#!/usr/bin/env python3
"""How much of a rigid rotation each scheme keeps: the spinning elastic ring (tests/scenes/spinning_ring.yaml,
docs/gpr-model.md 3.11) run with each scheme on each mesh size, its angular momentum about the centre of mass
(summary.json's figure, recomputed from every dump) against time, written as OUT.csv (scheme, mesh size, cells, t,
L / L0, kinetic energy / its start) and OUT.png beside it.

usage: rotation_study.py UNILAG OUT.csv [SIZES] [END]
  SIZES: comma-separated mesh sizes (default 0.025,0.0125); END: end time (default 15, half a turn)
"""
import csv
import glob
import os
import subprocess

import h5py
import numpy as np

import script_args

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "tests", "scenes", "spinning_ring.yaml")
SCHEMES = [("order 1", ["scheme.order=1"]),
           ("order 2, barth_jespersen", ["scheme.limiter=barth_jespersen"]),
           ("order 2, node_fit", ["scheme.limiter=node_fit"]),
           ("order 2, vertex_based", ["scheme.limiter=vertex_based"]),
           ("order 2, none", ["scheme.limiter=none"])]


def spin(path):
    """Time, angular momentum about the centre of mass and kinetic energy of one dump."""
    with h5py.File(path) as f:
        x, c, v = f["coordinates"][:, :2], f["connectivity"][:], f["velocity"][:, :2]
        m = (f["density"][:] * f["volume"][:]).ravel()
    with open(path.replace(".h5", ".xmf")) as f:
        t = float(f.read().split('Time Value="')[1].split('"')[0])
    centroid = x[c].mean(axis=1)
    xc = (m[:, None] * centroid).sum(axis=0) / m.sum()
    vc = (m[:, None] * v).sum(axis=0) / m.sum()
    r, u = centroid - xc, v - vc
    return t, (m * (r[:, 0] * u[:, 1] - r[:, 1] * u[:, 0])).sum(), 0.5 * (m * (v ** 2).sum(axis=1)).sum()


def main():
    args = script_args.positional(2, __doc__, 4)
    unilag, out = args[:2]
    if not os.access(unilag, os.X_OK):
        script_args.fail(f"UNILAG: {unilag} is not an executable")
    sizes = [script_args.number(s, "SIZES") for s in (args[2] if len(args) > 2 else "0.025,0.0125").split(",")]
    end = script_args.number(args[3], "END") if len(args) > 3 else 15.0
    work = os.path.splitext(out)[0] + "_runs"
    rows = []
    for h in sizes:
        for name, sets in SCHEMES:
            run = os.path.join(work, f"{name.replace(', ', '_').replace(' ', '')}_h{h}")
            cmd = [unilag, "run", SCENE, "--quiet", "--output", run, "--set", f"mesh.size={h}",
                   "--set", f"time.end={end}", "--set", f"output.interval={end / 30}"]
            for s in sets:
                cmd += ["--set", s]
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
            series = [spin(p) for p in sorted(glob.glob(os.path.join(run, "unilag_*.h5")))]
            with h5py.File(sorted(glob.glob(os.path.join(run, "unilag_*.h5")))[0]) as f:
                cells = len(f["density"])
            t0, l0, k0 = series[0]
            for t, l, k in series:
                rows.append((name, h, cells, t, l / l0, k / k0))
            print(f"{name:26s} h {h:<7g} {cells:6d} cells: L/L0 {series[-1][1] / l0:.4f}, "
                  f"kinetic energy kept {series[-1][2] / k0:.4f} at t = {series[-1][0]:g}")
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scheme", "mesh_size", "cells", "t", "angular_momentum_ratio", "kinetic_energy_ratio"])
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for k, (name, _) in enumerate(SCHEMES):
        for j, h in enumerate(sizes):
            mine = [r for r in rows if r[0] == name and r[1] == h]
            ax.plot([r[3] for r in mine], [r[4] for r in mine], color=f"C{k}", ls=["-", "--", ":"][j % 3],
                    label=f"{name}, {mine[0][2]} cells")
    ax.set_xlabel("t (half a turn at t = 15)")
    ax.set_ylabel("angular momentum / its start")
    ax.set_title("spinning elastic ring: the rotation each scheme keeps")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.splitext(out)[0] + ".png", dpi=120)
    print(f"wrote {out} and {os.path.splitext(out)[0]}.png")


if __name__ == "__main__":
    main()
