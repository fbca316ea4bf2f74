#!/usr/bin/env python3
"""A strong planar shock on tetrahedra: the scatter it leaves behind, and how much of it no node force can relax.

Runs tests/scenes/piston3d_tets.yaml (a piston at speed 1 into gas at rest, gamma 1.4, gmsh's unstructured
tetrahedra; exact density 6, pressure 1.2, internal energy 1/2 behind the shock) at order 1 and order 2, without and
with the entropy filter (scheme.entropy_filter 0.05 and 0.25), and measures the middle of the shocked layer as the
test piston3d_tets does (tests/scripts/piston3d.py: volume-weighted means, cell-to-cell scatter). It also splits the
pressure scatter by what the nodes see: the net node forces of the cells' pressures are F_r = sum_i p_i c_ir
(c_ir the corner vectors); the part of the pressure deviation in the kernel of p -> F exerts no force on any node
and is never relaxed. The kernel fraction of the measured deviation is printed beside that of random noise on the
same cells (docs/sedov.md, session 29). Nodes on the side walls keep their two tangential components; nodes of
cells outside the layer are left out. For comparison, the kernel fraction of random noise in pressures at the nodes,
acting through each cell's mean of its nodes' pressures (F_s = sum_r p_r dV_r/dx_s with nodal volumes V_r = sum |T_i|
/ 4, the average-nodal-pressure tetrahedron of solid mechanics): one pressure per node instead of per cell
(docs/sedov.md, session 30).
Printed and written as CSV; PNG beside it: the scatters and the kernel fraction per run.

usage: piston3d_scatter_study.py UNILAG OUT.csv [SIZE]     (SIZE: mesh size, default the scene's 0.03)
"""
import csv
import glob
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np
import scipy.sparse as sparse
import scipy.sparse.linalg as sparse_linalg

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(ROOT, "tests", "scripts"))
from piston3d import measure  # noqa: E402  (the test's own measure of the shocked layer)

SCENE = os.path.join(ROOT, "tests", "scenes", "piston3d_tets.yaml")
RUNS = {"o1": ["scheme.order=1"], "o2": ["scheme.order=2"],
        "o1_ef0.05": ["scheme.order=1", "scheme.entropy_filter=0.05"],
        "o2_ef0.05": ["scheme.order=2", "scheme.entropy_filter=0.05"],
        "o1_ef0.25": ["scheme.order=1", "scheme.entropy_filter=0.25"]}
WIDTH = 0.2  # the bar's cross-section, [0, WIDTH]^2


def corner_vectors(p):
    """c_ik = d|T_i|/dx_k of each tetrahedron (points p: cells x 4 x 3)."""
    c = np.zeros_like(p)
    for k in range(4):
        a, b, d = (p[:, j] for j in range(4) if j != k)
        n = np.cross(b - a, d - a) / 6.0
        c[:, k] = n * np.sign(np.einsum("ij,ij->i", n, p[:, k] - a))[:, None]
    return c


def kernel_fractions(run, layer):
    """The share of the pressure deviation's variance (and of random noise's) that p -> F does not see, and that of
    random noise in nodal pressures (each cell's pressure the mean of its nodes')."""
    with h5py.File(sorted(glob.glob(f"{run}/unilag_*.h5"))[-1], "r") as f:
        x, cells, p = f["coordinates"][:], f["connectivity"][:], f["pressure"][:, 0]
    c = corner_vectors(x[cells])
    inside = np.where(layer)[0]
    touched = np.zeros(len(x), bool)
    touched[cells[inside].ravel()] = True
    outside = np.zeros(len(x), bool)
    outside[cells[~layer].ravel()] = True
    nodes = np.where(touched & ~outside)[0]
    index = -np.ones(len(x), int)
    index[nodes] = np.arange(len(nodes))
    wall = [np.zeros(len(x), bool)] + [(x[:, d] < 1e-9) | (x[:, d] > WIDTH - 1e-9) for d in (1, 2)]
    rows, cols, vals = [], [], []
    for j, i in enumerate(inside):
        for k in range(4):
            r = cells[i, k]
            for d in range(3):
                if index[r] >= 0 and not wall[d][r]:
                    rows.append(3 * index[r] + d)
                    cols.append(j)
                    vals.append(c[i, k, d])
    forces = sparse.csr_matrix((vals, (rows, cols)), shape=(3 * len(nodes), len(inside)))

    def fraction(dp):
        y = sparse_linalg.lsqr(forces.T, dp, atol=1e-12, btol=1e-12, iter_lim=20000)[0]
        return np.sum((dp - forces.T @ y) ** 2) / np.sum(dp ** 2)

    dp = p[inside] - p[inside].mean()
    rng = np.random.default_rng(1)
    noise = fraction(dp), fraction(rng.standard_normal(len(inside)))
    mean = [(j, index[r]) for j, i in enumerate(inside) for r in cells[i] if index[r] >= 0]
    to_cells = sparse.csr_matrix(([0.25] * len(mean), tuple(zip(*mean))), shape=(len(inside), len(nodes)))
    nodal = (forces @ to_cells).tocsr()
    q = rng.standard_normal(len(nodes))
    y = sparse_linalg.lsqr(nodal.T, q, atol=1e-12, btol=1e-12, iter_lim=20000)[0]
    return noise + (np.sum((q - nodal.T @ y) ** 2) / np.sum(q ** 2),)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    unilag, out_csv = sys.argv[1], sys.argv[2]
    size = ["--set", f"mesh.size={sys.argv[3]}"] if len(sys.argv) == 4 else []
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name, sets in RUNS.items():
            run = os.path.join(work, name)
            args = [unilag, "run", SCENE, "--quiet", "--output", run] + size
            for s in sets:
                args += ["--set", s]
            subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
            m = measure(run)
            seen, noise, nodal = kernel_fractions(run, m["layer"])
            means, sc = m["means"], m["scatter"]
            rows.append({"run": name, "cells": m["summary"]["cells"], "steps": m["summary"]["steps"],
                         "density": means["density"][0], "pressure": means["pressure"][0],
                         "internal_energy": means["internal energy"][0],
                         "scatter_pressure": sc["pressure"], "scatter_density": sc["density"],
                         "scatter_internal_energy": sc["internal energy"], "largest_density": m["largest_density"],
                         "kernel_fraction": seen, "kernel_fraction_noise": noise,
                         "kernel_fraction_noise_nodal": nodal})
            r = rows[-1]
            print(f"{name:10s} density {r['density']:.4f} pressure {r['pressure']:.4f} eps {r['internal_energy']:.4f}"
                  f" | scatter p {100 * r['scatter_pressure']:.1f}% rho {100 * r['scatter_density']:.1f}% eps "
                  f"{100 * r['scatter_internal_energy']:.1f}% | largest rho {r['largest_density']:.2f} | in the kernel "
                  f"{100 * seen:.0f}% (noise {100 * noise:.0f}%; nodal pressures' noise {nodal:.0e})",
                  flush=True)
    with open(out_csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.splitext(out_csv)[0] + ".png")
    return 0


def plot(rows, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [r["run"] for r in rows]
    at = np.arange(len(rows))
    fig, ax = plt.subplots(figsize=(8, 4))
    for k, (key, label) in enumerate([("scatter_pressure", "pressure scatter"), ("scatter_density", "density scatter"),
                                      ("scatter_internal_energy", "internal energy scatter"),
                                      ("kernel_fraction", "share of the pressure variance no node sees")]):
        ax.bar(at + 0.2 * (k - 1.5), [100 * r[key] for r in rows], 0.2, label=label)
    ax.set_xticks(at)
    ax.set_xticklabels(names)
    ax.set_ylabel("%")
    ax.set_title("strong planar shock on tetrahedra (piston3d_tets): behind the shock")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    sys.exit(main())
