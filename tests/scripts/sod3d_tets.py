#!/usr/bin/env python3
"""Sod's shock tube on flat tetrahedra (docs/sod.md): the time step's relaxation length (docs/gpr-model.md 1.5) keeps
the cell velocities' relaxation through the nodal solver stable. Each run with --check; the fields are read from the
last HDF5 dump.

- inputs/sod3d.yaml (split prisms), order 2 (midpoint, the default limiter), CFL 0.5, to t = 0.1: the largest
  transverse cell velocity |(v_y, v_z)| <= 0.2 (the exact solution has none; measured 0.10 with barth_jespersen, 0.075
  with node_fit, and 1.37 in one cell at the contact before the relaxation length, which ran away from its nodes), in
  <= 300 steps (251, node_fit 243; 391 before, when that cell's shock term shrank the step).
- the same bar meshed with gmsh's unstructured tetrahedra (tests/meshes/bar3d_unstructured.geo), order 1, to t = 0.06:
  no density above the data's largest, 1 (1e-3; before, a cell at the contact was crushed to 10.5 with its internal
  energy falling from 2.0 to 0.04, an entropy decrease) and the smallest cell keeps >= 0.25 of the smallest initial
  volume (0.57; 0.018 before). Cells that straddle x = 0 take the right state at their centroid and a few of them end
  at density 0.06, an error of the start that the Lagrangian contact keeps (docs/sod.md); with
  `regions.gas.sampling: average` (the mean mass, momentum and energy over 20 points of each cell) the density stays
  within the data's [0.125, 1] (1e-3; measured 0.1250 .. 1.0000).

usage: sod3d_tets.py UNILAG INPUTS TESTS_MESHES WORKDIR
"""
import glob
import json
import os
import subprocess
import sys

import h5py
import numpy as np


def run(unilag, scene, out, options):
    subprocess.run([unilag, "run", scene, "--quiet", "--check", "--set", "exact.max_l1_density=0", "--output", out,
                    *options], check=True)
    with open(f"{out}/summary.json") as f:
        steps = json.load(f)["steps"]
    dumps = sorted(glob.glob(f"{out}/unilag_[0-9]*.h5"))
    fields = []
    for name in (dumps[0], dumps[-1]):
        with h5py.File(name, "r") as h:
            fields.append({k: h[k][:] for k in ("velocity", "density", "volume")})
    return steps, fields[0], fields[-1]


def main():
    unilag, inputs, meshes, work = sys.argv[1:5]
    fails = []

    def expect(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            fails.append(what)

    steps, _, last = run(unilag, f"{inputs}/sod3d.yaml", f"{work}/split_o2",
                         ["--set", "scheme.order=2", "--set", "time.end=0.1", "--set", "output.interval=0.1"])
    transverse = np.hypot(last["velocity"][:, 1], last["velocity"][:, 2]).max()
    expect(transverse <= 0.2, f"split prisms, order 2: largest transverse velocity {transverse:.3f} (<= 0.2)")
    expect(steps <= 300, f"split prisms, order 2: {steps} steps to t = 0.1 (<= 300)")

    steps, first, last = run(unilag, f"{inputs}/sod3d.yaml", f"{work}/unstructured_o1",
                             ["--set", f"mesh.geometry={os.path.abspath(meshes)}/bar3d_unstructured.geo", "--set", "scheme.order=1",
                              "--set", "time.end=0.06", "--set", "output.interval=0.06"])
    rho = last["density"][:, 0]
    expect(rho.max() <= 1 + 1e-3, f"unstructured, order 1: largest density {rho.max():.4f} (<= 1)")
    shrink = last["volume"].min() / first["volume"].min()
    expect(shrink >= 0.25, f"unstructured, order 1: smallest volume {shrink:.3f} of the initial smallest (>= 0.25)")
    print(f"unstructured, order 1: {steps} steps to t = 0.06")

    _, _, last = run(unilag, f"{inputs}/sod3d.yaml", f"{work}/unstructured_o1_average",
                     ["--set", f"mesh.geometry={os.path.abspath(meshes)}/bar3d_unstructured.geo", "--set",
                      "regions.gas.sampling=average", "--set", "scheme.order=1", "--set", "time.end=0.06", "--set",
                      "output.interval=0.06"])
    rho = last["density"][:, 0]
    expect(rho.min() >= 0.125 * (1 - 1e-3) and rho.max() <= 1 + 1e-3,
           f"unstructured, order 1, sampling: average: density in [{rho.min():.4f}, {rho.max():.4f}] (the data's "
           "[0.125, 1])")
    print("sod3d_tets:", "FAIL" if fails else "PASS")
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
