#!/usr/bin/env python3
"""Rotation invariance of order 2 with heat conduction in 3D: a bar of tetrahedra with free, adiabatic sides (the
heat quantities mirror there, the mechanics does not) sheared so that the sides bend, and the same bar turned by 90
degrees about z (node i at (-y_i, x_i, z_i), the same numbering, the initial data turned alike). An unlimited linear
reconstruction commutes with rotations, so the two runs must agree to the floor that the Picard iterations' tolerance
(1e-10) sets where round-off changes an iteration count (order 1 here: 1.6e-10 in J; order 2: 1.2e-10 in the
temperature, 1.6e-9 in J). They differed by 3e-6 in the temperature and 3e-4 in J when a node's mirror images composed
the reflections across its (no longer orthogonal) planes in the order the planes were found, which the cells' Morton
numbering changes with the rotation.

usage: heat_rotation3d.py UNILAG WORKDIR
"""
import glob
import os
import subprocess
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps"))
from msh22 import write_msh22  # noqa: E402

SCENE = """unilag:
  title: heat_rotation
  mesh: {{ file: {mesh} }}
  materials:
    gas:
      eos: ideal_gas
      gamma: 1.4
      cv: 2.5
      rho0: 1.0
      heat_conduction: {{ alpha: 2.0, kappa: 0.02, reference_temperature: 1.0 }}
  regions:
    gas: {{ material: gas, density: "{density} < 0.05 ? 1 : 0.8", pressure: 1.0, velocity: {velocity} }}
  boundaries:
    left: {{ type: slip_wall }}
    right: {{ type: slip_wall }}
    sides: {{ type: pressure, pressure: 1.0 }}
  scheme: {{ order: 2, limiter: none }}
  time: {{ end: 0.15, cfl: 0.5 }}
  output: {{ interval: 0 }}
"""
TURNED = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])  # x' = TURNED x


def bar(nx=40, ny=4, nz=4):
    """Nodes and positively oriented tetrahedra (six a hexahedron) of [-0.5, 0.5] x [0, 0.1]^2, and its boundary
    triangles with their groups (1 left, 2 right, 3 sides)."""
    g = np.stack(np.meshgrid(np.linspace(-0.5, 0.5, nx + 1), np.linspace(0, 0.1, ny + 1),
                             np.linspace(0, 0.1, nz + 1), indexing="ij"), -1).reshape(-1, 3)
    node = lambda i, j, k: (i * (ny + 1) + j) * (nz + 1) + k  # noqa: E731
    tets = []
    for i in range(nx):
        for j in range(ny):
            for k in range(nz):
                c = [node(i + a, j + b, k + d) for a in (0, 1) for b in (0, 1) for d in (0, 1)]
                for path in ((4, 6), (4, 5), (2, 6), (2, 3), (1, 5), (1, 3)):  # Kuhn: corner 0 to 7 by way of two
                    t = [c[0], c[path[0]], c[path[1]], c[7]]
                    v = np.dot(np.cross(g[t[1]] - g[t[0]], g[t[2]] - g[t[0]]), g[t[3]] - g[t[0]])
                    tets.append(t if v > 0 else [t[0], t[2], t[1], t[3]])
    faces = {}
    for t in tets:
        for f in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
            key = tuple(sorted(t[m] for m in f))
            faces[key] = faces.get(key, 0) + 1
    tris = []
    for f, count in faces.items():
        if count == 1:
            x = g[list(f), 0]
            tris.append((1 if np.all(x < -0.4999) else 2 if np.all(x > 0.4999) else 3, f))
    return g, np.array(tets), tris


def write_mesh(path, coords, tets, tris):
    groups = [(2, 1, "left"), (2, 2, "right"), (2, 3, "sides"), (3, 4, "gas")]
    elements = [(2, tag, [n + 1 for n in f]) for tag, f in tris] + [(4, 4, [n + 1 for n in t]) for t in tets]
    write_msh22(path, groups, coords, elements)


def run(unilag, work, name, mesh, density, velocity):
    scene = os.path.join(work, name + ".yaml")
    with open(scene, "w") as f:
        f.write(SCENE.format(mesh=mesh, density=density, velocity=velocity))
    out = os.path.join(work, name)
    subprocess.run([unilag, "run", scene, "--quiet", "--threads", "1", "--output", out], check=True)
    return sorted(glob.glob(os.path.join(out, "unilag_*.h5")))


def cells(dumps, back):
    """Initial centroids turned back by `back`, and the last dump's fields (vectors turned back)."""
    with h5py.File(dumps[0], "r") as f:
        x = f["coordinates"][:] @ back.T
        centroid = x[f["connectivity"][:]].mean(1)
    with h5py.File(dumps[-1], "r") as f:
        fields = {k: f[k][:] @ back.T if f[k].shape[1] == 3 else f[k][:] for k in ("temperature", "density",
                                                                                  "thermal_impulse", "velocity")}
    order = np.lexsort(np.round(centroid, 9).T[::-1])
    return {k: v[order] for k, v in fields.items()}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    unilag, work = sys.argv[1:]
    os.makedirs(work, exist_ok=True)
    coords, tets, tris = bar()
    write_mesh(os.path.join(work, "bar.msh"), coords, tets, tris)
    write_mesh(os.path.join(work, "bar_z90.msh"), coords @ TURNED.T, tets, tris)
    a = cells(run(unilag, work, "bar", os.path.join(work, "bar.msh"), "(x + 0.5*y + 0.3*z)",
                  '[0.0, "0.2*x", "0.1*x"]'), np.eye(3))
    b = cells(run(unilag, work, "bar_z90", os.path.join(work, "bar_z90.msh"), "(y - 0.5*x + 0.3*z)",
                  '["-0.2*y", 0.0, "0.1*y"]'), TURNED.T)
    ok = True
    for k in a:
        rel = np.abs(a[k] - b[k]).max() / np.abs(a[k]).max()
        print(f"{k:16s} largest difference {rel:.2e} of its largest value")
        ok &= rel < 1e-7
    print(f"{len(tets)} tetrahedra; bound 1e-7")
    print("heat_rotation3d: PASS" if ok else "heat_rotation3d: FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
