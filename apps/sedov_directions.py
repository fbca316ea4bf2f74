#!/usr/bin/env python3
"""Where a 2D Sedov run's density error lies by direction, against the mesh's edge directions.

For each run folder (a quadrant run of inputs/sedov2d.yaml with an output at t = 1): the L1 error of the density
against the scene's exact profile, summed over 3-degree sectors of the polar angle theta, and the three most common
edge directions of the initial mesh (gmsh's frontal mesh of the quadrant is a near-equilateral lattice whose
orientation depends on the size). A shock front is parallel to an edge family where theta = edge direction + 90
degrees. Prints one line per run, writes the sectors as CSV and a PNG beside it.

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


def sectors(h5, exact):
    with h5py.File(h5, "r") as f:
        x, cells = f["coordinates"][:, :2], f["connectivity"][...]
        rho, vol = f["density"][:, 0], f["volume"][:, 0]
    c = x[cells].mean(axis=1)
    r, theta = np.hypot(c[:, 0], c[:, 1]), np.degrees(np.arctan2(c[:, 1], c[:, 0]))
    err = np.abs(rho - np.interp(r, exact[:, 0], exact[:, 1], right=1.0)) * vol
    edges = np.arange(0, 90 + SECTOR, SECTOR)
    share = np.array([err[(theta >= a) & (theta < b)].sum() for a, b in zip(edges[:-1], edges[1:])])
    return share / vol.sum(), len(rho)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    exact = np.loadtxt(TABLE, delimiter=",", comments="#")
    out_csv, runs = sys.argv[1], sys.argv[2:]
    table = {}
    for run in runs:
        dumps = sorted(glob.glob(f"{run}/unilag_*.h5"))
        share, cells = sectors(dumps[-1], exact)
        dirs = edge_directions(dumps[0])
        normals = [(d + 90) % 180 for d in dirs]  # theta where the front is parallel to that edge family
        parallel = sorted([t for t in normals if t <= 95] + [t - 180 for t in normals if t >= 175])
        table[run] = share
        print(f"{run}: {cells} cells, L1 {share.sum():.5f}, edges at {dirs} deg (front parallel at theta {parallel}); "
              f"largest sectors from theta {sorted(SECTOR * int(k) for k in np.argsort(share)[::-1][:4])}")
    with open(out_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["theta_from", "theta_to"] + [os.path.basename(os.path.normpath(r)) for r in runs])
        for k in range(90 // SECTOR):
            w.writerow([SECTOR * k, SECTOR * (k + 1)] + [f"{table[r][k]:.6e}" for r in runs])
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4))
    mid = SECTOR * (np.arange(90 // SECTOR) + 0.5)
    for run in runs:
        ax.step(mid, table[run] / SECTOR, where="mid", label=os.path.basename(os.path.normpath(run)))
    ax.set_xlabel("theta (degrees)")
    ax.set_ylabel("L1(density) per degree")
    ax.set_xlim(0, 90)
    ax.legend(fontsize=8)
    ax.set_title("Sedov, t = 1: the density error by direction")
    fig.tight_layout()
    fig.savefig(os.path.splitext(out_csv)[0] + ".png", dpi=120)
    print(f"wrote {out_csv} and the PNG beside it")


if __name__ == "__main__":
    main()
