"""gmsh's ASCII format 2.2, the one unilag reads besides .geo: written by the studies and test scripts that build
their own meshes (apps/shock_orientation_study.py, tests/scripts/symmetry_mirror.py)."""


def write_msh22(path, groups, coords, elements):
    """groups: (dimension, physical tag, name) of each physical group; coords: the nodes' (x, y[, z]), numbered from 1
    in order; elements: (gmsh element type, physical tag, node numbers from 1)."""
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(groups))]
    lines += [f'{dim} {tag} "{name}"' for dim, tag, name in groups]
    lines += ["$EndPhysicalNames", "$Nodes", str(len(coords))]
    for k, x in enumerate(coords):
        xyz = tuple(float(v) for v in x) + (0.0,) * (3 - len(x))
        lines.append(f"{k + 1} {xyz[0]!r} {xyz[1]!r} {xyz[2]!r}")
    lines += ["$EndNodes", "$Elements", str(len(elements))]
    for e, (etype, tag, enodes) in enumerate(elements):
        lines.append(f"{e + 1} {etype} 2 {tag} {tag} " + " ".join(str(n) for n in enodes))
    lines.append("$EndElements")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
