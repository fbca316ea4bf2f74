#!/usr/bin/env python3
"""Time order of the order-2 integrators at a fixed mesh (docs/gpr-model.md 2.6): scheme.integrator midpoint and
ars222 on SCENE (inputs/vortex2d.yaml) at each CFL number and at a reference CFL, both integrators against their own
reference run. The difference is the volume-weighted L2 norm of the final cell velocities (matched by global id; the
cells are Lagrangian, so the same cells at slightly different places), and the observed order is
log(d_k / d_{k+1}) / log(cfl_k / cfl_{k+1}). summary.json's l2_error.velocity (against the exact vortex) and the wall
time are listed too. time.max_growth = 20 makes every step proportional to the CFL number (after the first, 0.1 of
it): the default ramp grows dt by 10% per step, i.e. dt ~ dt_0 + 0.1 t whatever the CFL number, which hides the order. Writes WORKDIR/ars_time_order.csv and WORKDIR/ars_time_order.png (difference against CFL).

usage: ars_time_order.py UNILAG SCENE WORKDIR [--cfl 0.8,0.4,0.2,0.1] [--ref 0.025] [--integrators midpoint,ars222]
                         [--set KEY=VALUE ...]
Runs one process at a time (OMP_NUM_THREADS as inherited).
"""
import csv
import glob
import json
import math
import os
import subprocess
import sys

import h5py
import numpy as np


def run(unilag, scene, out, integrator, cfl, extra):
    cmd = [unilag, "run", scene, "--quiet", "--output", out, "--set", "scheme.order=2", "--set",
           f"scheme.integrator={integrator}", "--set", f"time.cfl={cfl}", "--set", "output.interval=0", "--set",
           "time.max_growth=20"] + extra
    subprocess.run(cmd, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def final_cells(out):
    """Velocity and volume of the final cells, sorted by global id."""
    with h5py.File(sorted(glob.glob(f"{out}/unilag_*.h5"))[-1], "r") as f:
        gid = f["global_id"][:, 0]
        vel = f["velocity"][...]
        xyz, conn = f["coordinates"][...], f["connectivity"][...]
    p = xyz[conn]
    if conn.shape[1] == 3:  # triangles
        a, b = p[:, 1, :2] - p[:, 0, :2], p[:, 2, :2] - p[:, 0, :2]
        vol = 0.5 * np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
    else:  # tetrahedra
        vol = np.abs(np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]))) / 6
    order = np.argsort(gid)
    return vel[order], vol[order]


def l2_difference(a, b):
    (va, wa), (vb, _) = a, b
    return math.sqrt(np.sum(wa * np.sum((va - vb) ** 2, axis=1)) / np.sum(wa))


def main():
    args = sys.argv[1:]
    if len(args) < 3:
        sys.exit(__doc__)
    unilag, scene, work = args[:3]
    cfls, ref, integrators, extra = [0.8, 0.4, 0.2, 0.1], 0.025, ["midpoint", "ars222"], []
    i = 3
    while i < len(args):
        if args[i] == "--cfl":
            cfls = [float(c) for c in args[i + 1].split(",")]
        elif args[i] == "--ref":
            ref = float(args[i + 1])
        elif args[i] == "--integrators":
            integrators = args[i + 1].split(",")
        elif args[i] == "--set":
            extra += ["--set", args[i + 1]]
        else:
            sys.exit(f"unknown argument {args[i]}\n{__doc__}")
        i += 2
    os.makedirs(work, exist_ok=True)
    rows = []
    for integ in integrators:
        out = os.path.join(work, f"{integ}_ref")
        s = run(unilag, scene, out, integ, ref, extra)
        reference = final_cells(out)
        print(f"{integ}: reference cfl {ref}: steps {s['steps']}, l2_error.velocity {s['l2_error']['velocity']:.6e}")
        prev = None
        for cfl in cfls:
            out = os.path.join(work, f"{integ}_cfl{cfl}")
            s = run(unilag, scene, out, integ, cfl, extra)
            d = l2_difference(final_cells(out), reference)
            order = math.log(prev[1] / d) / math.log(prev[0] / cfl) if prev else float("nan")
            prev = (cfl, d)
            row = {"integrator": integ, "cfl": cfl, "steps": s["steps"], "wall_seconds": s["wall_seconds"],
                   "l2_error_velocity": s["l2_error"]["velocity"], "l2_difference_velocity": d, "order": order}
            rows.append(row)
            print(f"  cfl {cfl:6.3f}: steps {s['steps']:5d} wall {s['wall_seconds']:7.2f} s  error {row['l2_error_velocity']:.6e}"
                  f"  |u - u_ref| {d:.4e}  order {order:5.2f}")
    with open(os.path.join(work, "ars_time_order.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(5, 4))
        for integ in integrators:
            r = [x for x in rows if x["integrator"] == integ]
            ax.loglog([x["cfl"] for x in r], [x["l2_difference_velocity"] for x in r], "o-", label=integ)
        c = np.array(cfls)
        d0 = rows[0]["l2_difference_velocity"]
        ax.loglog(c, d0 * (c / c[0]) ** 2, "k--", lw=0.8, label="slope 2")
        ax.set_xticks(cfls)
        ax.set_xticks([], minor=True)
        ax.set_xticklabels([f"{c:g}" for c in cfls])
        ax.set_xlabel("CFL")
        ax.set_ylabel(f"L2 |u - u(cfl {ref})|")
        ax.legend()
        ax.set_title(os.path.basename(scene) + (" " + " ".join(extra[1::2]) if extra else ""), fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(work, "ars_time_order.png"), dpi=120)
    except ImportError:
        pass


if __name__ == "__main__":
    main()
