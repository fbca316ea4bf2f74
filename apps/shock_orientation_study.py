#!/usr/bin/env python3
"""A planar strong shock on triangles of three orientations: how much entropy scatter the mesh leaves behind it.

A piston at speed 1 drives a shock into a cold ideal gas (gamma 5/3, density 1, pressure 0, the piston of
tests/scenes/piston_cold2d.yaml): exact density 4 behind the shock, which runs at 4/3. The same run on
  - strip:   gmsh's transfinite strip (inputs/geometry/strip2d.geo, alternating diagonals): vertical edges, parallel
             to the shock front;
  - lattice_x: an equilateral lattice with one edge family along x, the direction of motion (no edge parallel to
             the front);
  - lattice_y: the same lattice turned by 90 degrees: one edge family parallel to the front,
at order 1 and with five order-2 schemes (barth_jespersen with all quantities reconstructed, vertex_based with all,
vertex_based with the velocity alone, barth_jespersen with vertex-based bounds on the pressure alone,
pressure_limiter: vertex_based, and the default node_fit with all), and order 1 and the velocity-alone order 2
with the entropy filter (scheme.entropy_filter: 0.05; `_ef`; not on lattice_x, which has no scatter to filter).
Printed and written as CSV:
the mean density behind the shock and its cell-to-cell standard deviation (the pressure there is uniform to 1e-4, so
the scatter is entropy); PNG beside it: density against x.

usage: shock_orientation_study.py UNILAG OUT.csv [SIZE] [--check MEAN_PERCENT ALIGNED_PERCENT]
SIZE: the mesh size (default 0.005). --check (the test piston_orientation): exit 1 unless every run's mean density
behind the shock is within MEAN_PERCENT of 4 (but the velocity-only scheme's, 2.8% high), lattice_x's scatter and
worst cell are within ALIGNED_PERCENT, the strip's with vertex_based and all reconstructed below a fifth of order
1's scatter there, the strip's scatter with pressure_limiter: vertex_based is below half of order 1's, and the
entropy filter at least halves the scatter of its two schemes on the strip and on lattice_y.
"""
import csv
import glob
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

from msh22 import write_msh22

SCENE = """unilag:
  title: piston_orientation
  mesh: {mesh}
  materials: {{ gas: {{ eos: ideal_gas, gamma: 1.6666666666666667 }} }}
  regions: {{ gas: {{ material: gas, density: 1.0, velocity: [0.0, 0.0], pressure: 0.0 }} }}
  boundaries:
    left: {{ type: velocity, velocity: [1.0, 0.0] }}
    right: {{ type: slip_wall }}
    top: {{ type: slip_wall }}
    bottom: {{ type: slip_wall }}
  time: {{ end: 0.5, cfl: 0.4 }}
  scheme: {{ {scheme} }}
  output: {{ directory: {out}, interval: 0.5 }}
"""
X0, LENGTH, T_END = -0.5, 1.0, 0.5
SCHEMES = {"o1": "order: 1", "o2": "order: 2, limiter: barth_jespersen", "o2_vb": "order: 2, limiter: vertex_based",
           "o2_vb_vel": "order: 2, limiter: vertex_based, reconstruct: velocity",
           "o2_pv": "order: 2, limiter: barth_jespersen, pressure_limiter: vertex_based",
           "o2_nf": "order: 2, limiter: node_fit",
           "o1_ef": "order: 1, entropy_filter: 0.05",
           "o2_vb_vel_ef": "order: 2, limiter: vertex_based, reconstruct: velocity, entropy_filter: 0.05"}
COLOURS = {"o1": "tab:blue", "o2": "tab:red", "o2_vb": "tab:green", "o2_vb_vel": "tab:orange", "o2_pv": "tab:purple",
           "o1_ef": "tab:cyan", "o2_nf": "tab:olive", "o2_vb_vel_ef": "tab:brown"}
FILTERED = {"o1_ef": "o1", "o2_vb_vel_ef": "o2_vb_vel"}  # a scheme with the entropy filter: the same without
# lattice_x leaves no scatter to filter (0.00-0.02% measured with the filter): those runs are skipped, for CI time
SKIPPED = {("lattice_x", f) for f in FILTERED}
X_PISTON, X_SHOCK, RHO_BEHIND = X0 + T_END, X0 + T_END * 4.0 / 3.0, 4.0


def lattice_msh(path, h, height, edges_along_x):
    """Equilateral lattice on [X0, X0 + LENGTH] x [0, height] as gmsh 2.2 (groups left/right/top/bottom, gas): rows
    of nodes along one axis, every other row shifted by half a spacing, a boundary node closing the shifted rows."""
    along, across = (LENGTH, height) if edges_along_x else (height, LENGTH)
    rows_n = max(1, int(round(across / (h * np.sqrt(3.0) / 2.0))))
    cols_n = max(1, int(round(along / h)))
    dy, dx = across / rows_n, along / cols_n
    nodes, rows = [], []
    for j in range(rows_n + 1):
        shift = 0.5 * dx if j % 2 else 0.0
        xs = [0.0] + [shift + i * dx for i in range(cols_n + 1) if 1e-12 < shift + i * dx < along - 1e-12] + [along]
        rows.append(list(range(len(nodes), len(nodes) + len(xs))))
        nodes += [(x, j * dy) for x in xs]
    nodes = np.array(nodes)
    tris = []
    for a, b in zip(rows[:-1], rows[1:]):  # zip two rows into a strip of triangles
        i = k = 0
        while i < len(a) - 1 or k < len(b) - 1:
            if k == len(b) - 1 or (i < len(a) - 1 and nodes[a[i + 1], 0] <= nodes[b[k + 1], 0]):
                tris.append((a[i], a[i + 1], b[k]))
                i += 1
            else:
                tris.append((a[i], b[k + 1], b[k]))
                k += 1
    sides = {"low": [(rows[0][i], rows[0][i + 1]) for i in range(len(rows[0]) - 1)],
             "high": [(rows[-1][i], rows[-1][i + 1]) for i in range(len(rows[-1]) - 1)],
             "start": [(a[0], b[0]) for a, b in zip(rows[:-1], rows[1:])],
             "end": [(a[-1], b[-1]) for a, b in zip(rows[:-1], rows[1:])]}
    if edges_along_x:
        names = {"low": "bottom", "high": "top", "start": "left", "end": "right"}
        xy = nodes + [X0, 0.0]
    else:  # swap the axes; reversing each triangle keeps it counter-clockwise
        names = {"low": "left", "high": "right", "start": "bottom", "end": "top"}
        xy = nodes[:, ::-1] + [X0, 0.0]
        tris = [(t[0], t[2], t[1]) for t in tris]
    tags = {"left": 1, "right": 2, "top": 3, "bottom": 4}
    elements = [(1, tags[names[s]], (p + 1, q + 1)) for s, segs in sides.items() for p, q in segs]
    elements += [(2, 5, tuple(v + 1 for v in t)) for t in tris]
    write_msh22(path, [(1, t, n) for n, t in tags.items()] + [(2, 5, "gas")], [tuple(p) for p in xy], elements)


def behind_shock(out):
    with h5py.File(sorted(glob.glob(f"{out}/unilag_*.h5"))[-1], "r") as f:
        xyz, conn, rho = f["coordinates"][...], f["connectivity"][...], f["density"][:, 0]
    xc = xyz[conn][:, :, 0].mean(axis=1)
    gap = X_SHOCK - X_PISTON
    zone = (xc > X_PISTON + 0.2 * gap) & (xc < X_SHOCK - 0.2 * gap)
    return xc, rho, rho[zone].mean(), rho[zone].std(), np.abs(rho[zone] / RHO_BEHIND - 1.0).max()


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    args = sys.argv[1:]
    check = None
    if "--check" in args:
        k = args.index("--check")
        check = (float(args[k + 1]), float(args[k + 2]))
        del args[k:k + 3]
    unilag, out_csv = os.path.abspath(args[0]), args[1]
    os.makedirs(os.path.dirname(os.path.abspath(out_csv)), exist_ok=True)  # before the runs, not after them
    size = float(args[2]) if len(args) > 2 else 0.005
    strip = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "inputs", "geometry", "strip2d.geo")
    rows, profiles = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        lattice_msh(f"{tmp}/lattice_x.msh", size, 0.05, True)
        lattice_msh(f"{tmp}/lattice_y.msh", size, 0.05, False)
        meshes = {"strip": f"{{ geometry: {os.path.abspath(strip)}, size: {size} }}",
                  "lattice_x": f"{{ file: {tmp}/lattice_x.msh }}", "lattice_y": f"{{ file: {tmp}/lattice_y.msh }}"}
        for name, mesh in meshes.items():
            for order, scheme in SCHEMES.items():
                if (name, order) in SKIPPED:
                    continue
                out = f"{tmp}/{name}_{order}"
                scene = f"{tmp}/{name}_{order}.yaml"
                with open(scene, "w") as f:
                    f.write(SCENE.format(mesh=mesh, scheme=scheme, out=out))
                subprocess.run([unilag, "run", scene, "--quiet"], check=True, stdout=subprocess.DEVNULL)
                xc, rho, mean, std, worst = behind_shock(out)
                profiles[(name, order)] = (xc, rho)
                rows.append({"mesh": name, "scheme": order, "cells": len(rho), "density_mean": f"{mean:.5f}",
                             "density_std": f"{std:.5f}", "scatter_percent": f"{100 * std / mean:.2f}",
                             "worst_cell_percent": f"{100 * worst:.2f}"})
                print(f"{name:10s} {order:9s}: {len(rho):6d} cells, density behind the shock {mean:.4f} "
                      f"(exact 4), scatter {100 * std / mean:5.2f}%, worst cell {100 * worst:5.2f}%")
    with open(out_csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.6), sharey=True)
    for ax, name in zip(axes, meshes):
        for order, colour in COLOURS.items():
            if (name, order) in SKIPPED:
                continue
            xc, rho = profiles[(name, order)]
            ax.plot(xc, rho, ".", ms=1.5, color=colour, label=order)
        ax.axhline(RHO_BEHIND, color="k", lw=0.6)
        ax.set_xlim(X_PISTON - 0.02, X_SHOCK + 0.05)
        ax.set_title(name)
        ax.set_xlabel("x")
    axes[0].set_ylabel("density (cells)")
    axes[0].legend(markerscale=6)
    fig.suptitle(f"cold piston, size {size}: entropy scatter behind a planar shock by edge orientation")
    fig.tight_layout()
    fig.savefig(os.path.splitext(out_csv)[0] + ".png", dpi=120)
    print(f"wrote {out_csv} and the PNG beside it")
    if check:
        bad = [r for r in rows if r["scheme"] != "o2_vb_vel" and  # reported, not asserted: 2.8% high (open)
               abs(float(r["density_mean"]) / RHO_BEHIND - 1.0) * 100 > check[0]]
        bad += [r for r in rows if r["mesh"] == "lattice_x" and
                max(float(r["scatter_percent"]), float(r["worst_cell_percent"])) > check[1]]
        scatter = {(r["mesh"], r["scheme"]): float(r["scatter_percent"]) for r in rows}
        # vertex bounds with all reconstructed remove most of the strip's scatter (0.29% with the pair weights of
        # the gradients before session 24, 1.3% with the node weights; order 1 9.4%)
        bad += [r for r in rows if (r["mesh"], r["scheme"]) == ("strip", "o2_vb") and
                max(float(r["scatter_percent"]), float(r["worst_cell_percent"])) > 0.2 * scatter[("strip", "o1")]]
        if scatter[("strip", "o2_pv")] > 0.5 * scatter[("strip", "o1")]:
            bad += [r for r in rows if (r["mesh"], r["scheme"]) == ("strip", "o2_pv")]
        for filtered, plain in FILTERED.items():  # the filter halves the scatter where an edge family faces the shock
            for mesh in ("strip", "lattice_y"):
                if scatter[(mesh, filtered)] > 0.5 * scatter[(mesh, plain)]:
                    bad += [r for r in rows if (r["mesh"], r["scheme"]) == (mesh, filtered)]
        for r in bad:
            print(f"FAIL: {r['mesh']} {r['scheme']}: mean {r['density_mean']}, scatter {r['scatter_percent']}%, "
                  f"worst {r['worst_cell_percent']}%")
        sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
