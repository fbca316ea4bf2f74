#!/usr/bin/env python3
"""Where a 2D Sedov run's density error lies by direction, against the mesh's edge directions and the front's shape.

For each run folder (a quadrant run of inputs/sedov2d.yaml with an output at t = 1): the L1 error of the density
against the scene's exact profile, summed over 3-degree sectors of the polar angle theta; the shock radius in each
sector (where the sector's ring-averaged density falls through 3.5, half way up the jump); and the three most common
edge directions of the initial mesh (gmsh's frontal mesh of the quadrant is a near-equilateral lattice whose
orientation depends on the size). A shock front is parallel to an edge family where theta = edge direction + 90
degrees. The L1 is also split by the front's shape: recomputed against the exact profile stretched, in each sector,
to that sector's shock radius ("L1 without the front's shape"), and to the mean radius. What the first removes is
the part of the error that a front out of round makes; what stays is the profile behind it.
Prints one line per run, writes the sectors (L1 share, front offset in 1e-3 of the exact radius) as CSV and a PNG
beside it.

usage: sedov_directions.py OUT.csv RUN_DIR [RUN_DIR ...]
"""
import csv
import glob
import os
import sys

import h5py
import numpy as np

TABLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "inputs", "exact",
                     "sedov_cyl_gamma1.4_E0.244816quadrant_t1.csv")
SECTOR = 3
SHOCK_RADIUS = 0.9988  # the exact table's, at t = 1
HALF_JUMP = 3.5  # density half way between 1 ahead of the shock and 6 behind it


def edge_directions(h5):
    with h5py.File(h5, "r") as f:
        x, cells = f["coordinates"][:, :2], f["connectivity"][...]
    p = x[cells]
    c = p.mean(axis=1)
    inner = (c[:, 0] > 0.3) & (c[:, 1] > 0.3)  # away from the planes' boundary layers
    angles = np.concatenate([np.degrees(np.arctan2(*(p[inner, (k + 1) % 3] - p[inner, k])[:, ::-1].T)) % 180
                             for k in range(3)])
    counts, _ = np.histogram(angles, bins=36, range=(0, 180))
    return sorted(int(5 * k + 2.5) for k in np.argsort(counts)[::-1][:3])


def front_radius(r, rho, vol, ring=0.004):
    """Outermost radius where the density averaged over overlapping rings (width `ring`) falls through HALF_JUMP."""
    starts = np.arange(0.9, 1.05, ring / 2)
    mean = np.array([(rho * vol)[k].sum() / vol[k].sum() if k.any() else 1.0
                     for k in ((r >= a) & (r < a + ring) for a in starts)])
    above = np.where(mean[:-1] > HALF_JUMP)[0]
    if above.size == 0 or mean[above.max() + 1] > HALF_JUMP:
        raise ValueError(f"no shock front between r = {starts[0]:.2f} and {starts[-1]:.2f}: is the last output at t = 1?")
    i = above.max()
    return starts[i] + ring / 2 + ring / 2 * (mean[i] - HALF_JUMP) / (mean[i] - mean[i + 1])


def analyse(h5, exact):
    with h5py.File(h5, "r") as f:
        x, cells = f["coordinates"][:, :2], f["connectivity"][...]
        rho, vol = f["density"][:, 0], f["volume"][:, 0]
    c = x[cells].mean(axis=1)
    r, theta = np.hypot(c[:, 0], c[:, 1]), np.degrees(np.arctan2(c[:, 1], c[:, 0]))
    edges = np.arange(0, 90 + SECTOR, SECTOR)
    in_sector = [(theta >= a) & (theta < b) for a, b in zip(edges[:-1], edges[1:])]
    fronts = np.array([front_radius(r[k], rho[k], vol[k]) for k in in_sector])

    def l1(scale):  # against the exact profile with its shock moved to radius SHOCK_RADIUS / scale
        return np.abs(rho - np.interp(r * scale, exact[:, 0], exact[:, 1], right=1.0)) * vol / vol.sum()

    err = l1(1.0)
    share = np.array([err[k].sum() for k in in_sector])
    per_sector = np.empty_like(r)
    for k, front in zip(in_sector, fronts):
        per_sector[k] = SHOCK_RADIUS / front
    return {"share": share, "cells": len(rho), "front": fronts / SHOCK_RADIUS - 1.0,
            "l1_mean_front": l1(SHOCK_RADIUS / fronts.mean()).sum(), "l1_sector_fronts": l1(per_sector).sum()}


def write_outputs(out_csv, runs, table):
    names = [os.path.basename(os.path.normpath(r)) for r in runs]
    with open(out_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["theta_from", "theta_to"] + [f"{n}_l1" for n in names] + [f"{n}_front_permil" for n in names])
        for k in range(90 // SECTOR):
            w.writerow([SECTOR * k, SECTOR * (k + 1)] + [f"{table[r]['share'][k]:.6e}" for r in runs] +
                       [f"{1e3 * table[r]['front'][k]:+.3f}" for r in runs])
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9.5, 6.5), sharex=True)
    mid = SECTOR * (np.arange(90 // SECTOR) + 0.5)
    for run, name in zip(runs, names):
        line = top.step(mid, table[run]["share"] / SECTOR, where="mid", label=name)[0]
        bottom.plot(mid, 1e3 * table[run]["front"], ".-", color=line.get_color(), label=name)
    top.set_ylabel("L1(density) per degree")
    top.set_title("Sedov, t = 1: the density error and the shock radius by direction")
    bottom.axhline(0.0, color="k", lw=0.6)
    bottom.set_ylabel("shock radius / exact - 1 (1e-3)")
    bottom.set_xlabel("theta (degrees)")
    bottom.set_xlim(0, 90)
    fig.tight_layout(rect=(0, 0, 0.84, 1))
    fig.legend(*top.get_legend_handles_labels(), loc="center right", fontsize=8)
    fig.savefig(os.path.splitext(out_csv)[0] + ".png", dpi=120)
    print(f"wrote {out_csv} and the PNG beside it")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    exact = np.loadtxt(TABLE, delimiter=",", comments="#")
    out_csv, runs = sys.argv[1], sys.argv[2:]
    table = {}
    for run in runs:
        dumps = sorted(glob.glob(f"{run}/unilag_*.h5"))
        try:
            table[run] = a = analyse(dumps[-1], exact)
        except ValueError as e:
            sys.exit(f"{dumps[-1]}: {e}")
        dirs = edge_directions(dumps[0])
        normals = [(d + 90) % 180 for d in dirs]  # theta where the front is parallel to that edge family
        parallel = sorted([t for t in normals if t <= 95] + [t - 180 for t in normals if t >= 175])
        print(f"{run}: {a['cells']} cells, L1 {a['share'].sum():.5f}, edges at {dirs} deg (front parallel at theta "
              f"{parallel}); largest sectors from theta "
              f"{sorted(SECTOR * int(k) for k in np.argsort(a['share'])[::-1][:4])}; shock radius / exact - 1: mean "
              f"{1e3 * a['front'].mean():+.2f}e-3, spread (sd) {1e3 * a['front'].std():.2f}e-3; L1 against the exact "
              f"profile at the mean radius {a['l1_mean_front']:.5f}, at each sector's {a['l1_sector_fronts']:.5f}")
    write_outputs(out_csv, runs, table)


if __name__ == "__main__":
    main()
