#!/usr/bin/env python3
"""Symmetry planes are the mirror problem (docs/gpr-model.md 3.3, "Symmetry planes"): a flow on the quadrant (2D) or
octant (3D) of GEO meshed by gmsh at SIZE, with symmetry planes on the coordinate planes, against the same flow on
that mesh mirrored across the planes into the whole square or cube, which has no planes. Every cell of the quadrant
must have the density of its copy in the mirrored mesh to MAX_REL_DIFF (relative) at every output: the nodal solver,
the walls, the first step's lagged node velocities and, at order 2, the reconstruction (the mirror images in the
stencil and the bounds) must treat a plane as the mirrored flow does. FLOW:
  sedov  Sedov's blast (2^D times the energy in the whole), slip-wall outer sides, to t = 0.3;
  noh    Noh's cold implosion (gamma 5/3, p = 0, v = -x/|x|), free outer sides, to t = 0.3.

usage: symmetry_mirror.py UNILAG GEO SIZE WORKDIR MAX_REL_DIFF FLOW [--set key=value ...]
"""
import glob
import itertools
import os
import subprocess
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps"))
from msh22 import write_msh22  # noqa: E402

ENERGY = {2: 0.244816, 3: 0.106384}  # the quadrant's / octant's share, as inputs/sedov2d.yaml and sedov3d.yaml
FACE_TYPE, CELL_TYPE = {2: 1, 3: 2}, {2: 2, 3: 4}  # gmsh element types: line, triangle / triangle, tetrahedron


def read_msh22(path):
    """Nodes (id -> xyz), physical names (tag -> name), and elements (type, physical tag, node ids)."""
    lines = open(path).read().split("\n")
    names = {}
    i = lines.index("$PhysicalNames")
    for k in range(int(lines[i + 1])):
        dim, tag, name = lines[i + 2 + k].split(maxsplit=2)
        names[int(tag)] = name.strip('"')
    i = lines.index("$Nodes")
    nodes = {}
    for k in range(int(lines[i + 1])):
        p = lines[i + 2 + k].split()
        nodes[int(p[0])] = tuple(float(v) for v in p[1:4])
    i = lines.index("$Elements")
    elements = []
    for k in range(int(lines[i + 1])):
        p = [int(v) for v in lines[i + 2 + k].split()]
        elements.append((p[1], p[3], p[3 + p[2]:]))
    return nodes, names, elements


def mirror_mesh(src, dst, dim):
    """Reflect the mesh across every subset of the planes x_d = 0 (d < dim); keep the outer faces and the cells."""
    nodes, names, elements = read_msh22(src)
    outer = [tag for tag, name in names.items() if name == "outer"][0]
    index, coords, faces, cells = {}, [], [], []

    def image(node, signs):
        x = tuple(s * v if v != 0.0 else 0.0 for s, v in zip(signs + (1,) * (3 - dim), nodes[node]))
        if x not in index:
            index[x] = len(coords) + 1
            coords.append(x)
        return index[x]

    for signs in itertools.product((1, -1), repeat=dim):
        flip = np.prod(signs) < 0  # an odd number of reflections turns the elements inside out
        for etype, tag, enodes in elements:
            if etype == FACE_TYPE[dim] and tag == outer:
                target = faces
            elif etype == CELL_TYPE[dim]:
                target = cells
            else:
                continue
            mapped = [image(n, signs) for n in enodes]
            if flip:
                mapped[0], mapped[1] = mapped[1], mapped[0]
            target.append(mapped)
    write_msh22(dst, [(dim - 1, 1, "outer"), (dim, 2, "gas")], coords,
                [(FACE_TYPE[dim], 1, a) for a in faces] + [(CELL_TYPE[dim], 2, a) for a in cells])
    return [name for name in names.values() if name not in ("outer", "gas")]


def scene(path, msh, dim, flow, parts, planes):
    """The scene of FLOW on mesh msh, which holds `parts` of the 2^dim quadrants or octants."""
    zero = ", ".join(["0.0"] * dim)
    bcs = "".join(f"    {name}: {{ type: symmetry }}\n" for name in planes)
    if flow == "sedov":
        gas = f"""  materials:
    gas: {{ eos: ideal_gas, gamma: 1.4 }}
  regions:
    gas: {{ material: gas, density: 1.0, velocity: [{zero}], pressure: 1.0e-6 }}
  energy_deposit: {{ position: [{zero}], energy: {ENERGY[dim] * parts!r} }}
"""
        outer = "slip_wall"
    else:
        inward = ", ".join(f'"-{c} / max(r, 1e-12)"' for c in "xyz"[:dim])
        gas = f"""  materials:
    gas: {{ eos: ideal_gas, gamma: 1.6666666666666667 }}
  regions:
    gas: {{ material: gas, density: 1.0, velocity: [{inward}], pressure: 0.0 }}
"""
        outer = "free"
    with open(path, "w") as f:
        f.write(f"""unilag:
  title: symmetry_mirror
  mesh: {{ file: {msh} }}
{gas}  boundaries:
{bcs}    outer: {{ type: {outer} }}
  time: {{ end: 0.3, cfl: 0.4 }}
  output: {{ directory: out, interval: 0.1 }}
""")


def centroids(path):
    with h5py.File(path, "r") as f:
        x, cells = f["coordinates"][()], f["connectivity"][()]
    return x[cells].mean(axis=1)


def main():
    if len(sys.argv) < 7 or sys.argv[6] not in ("sedov", "noh"):
        sys.exit(__doc__)
    unilag, geo, size, work, bound, flow = sys.argv[1:5] + [float(sys.argv[5]), sys.argv[6]]
    sets = sys.argv[7:]
    os.makedirs(work, exist_ok=True)
    dim = 3 if "Box" in open(geo).read() or "Volume" in open(geo).read() else 2
    quadrant, whole = f"{work}/part.msh", f"{work}/whole.msh"
    subprocess.run(["gmsh", f"-{dim}", geo, "-format", "msh22", "-o", quadrant, "-v", "1",
                    "-setnumber", "Mesh.MeshSizeMin", size, "-setnumber", "Mesh.MeshSizeMax", size,
                    "-setnumber", "Mesh.MeshSizeFromPoints", "0", "-setnumber", "Mesh.MeshSizeFromCurvature", "0",
                    "-setnumber", "Mesh.MeshSizeExtendFromBoundary", "0"], check=True)
    planes = mirror_mesh(quadrant, whole, dim)
    runs = {}
    for name, msh, parts, bcs in (("part", quadrant, 1, planes), ("whole", whole, 2 ** dim, [])):
        scene(f"{work}/{name}.yaml", msh, dim, flow, parts, bcs)
        out = f"{work}/{name}_out"
        subprocess.run([unilag, "run", f"{work}/{name}.yaml", "--quiet", "--output", out] + sets, check=True)
        runs[name] = sorted(glob.glob(f"{out}/unilag_*.h5"))
    # the quadrant's cells in the mirrored mesh, by their centroids at t = 0 (the mirror writes the same coordinates)
    key = lambda c: [tuple(v) for v in np.round(c * 1e9).astype(np.int64)]
    where = {k: j for j, k in enumerate(key(centroids(runs["whole"][0])))}
    match = np.array([where.get(k, -1) for k in key(centroids(runs["part"][0]))])
    ok = (match >= 0).all() and len(runs["part"]) == len(runs["whole"]) > 1
    worst = 0.0
    for a, b in zip(runs["part"], runs["whole"]):
        with h5py.File(a, "r") as fa, h5py.File(b, "r") as fb:
            rho_a, rho_b = fa["density"][:, 0], fb["density"][:, 0][match]
        worst = max(worst, float(np.max(np.abs(rho_a - rho_b) / rho_b)))
    ok = ok and worst <= bound
    print(f"{flow}, {dim}D, {len(match)} cells against {2 ** dim} x: largest relative density difference {worst:.3g} "
          f"(bound {bound:g}) over {len(runs['part'])} outputs")
    print("symmetry_mirror:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
