"""The 2D Sedov quadrant [0, 1.2]^2 as an equilateral lattice with no small cell along either symmetry plane
(docs/sedov-peak.md, session 35): rows of nodes along y = 0 (the x axis plane is a lattice line), and in every
odd row but the first the node half a cell from x = 0 (and from x = 1.2) moved onto the line, so that the cells
along x = 0 are a full triangle and one of 1.5 times the area instead of a half cell (gmsh's frontal quadrant has a
seam of half-size cells along a plane). The first odd row keeps its half cell: the energy deposit goes into the
cells around the origin's node, and one right triangle there alone made the blast lopsided (L1 0.037 at 16k).

usage: sedov_lattice_mesh.py SIZE OUT.msh   (SIZE as the scene's mesh.size: 0.0144 gives about 16k triangles)
Groups: axis_x (y = 0), axis_y (x = 0), outer, gas, as inputs/geometry/quadrant2d.geo names them."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from msh22 import write_msh22  # noqa: E402
from script_args import fail, number, positional  # noqa: E402

SIDE = 1.2


def rows_of_nodes(size):
    """The x of each row's nodes; row j lies at y = j * height."""
    nx = max(2, round(SIDE / size))
    ny = max(2, round(SIDE / (size * math.sqrt(3) / 2)))
    base = SIDE / nx
    rows = []
    for j in range(ny + 1):
        if j % 2 == 0:
            rows.append([i * base for i in range(nx + 1)])
        else:
            inner = [(i + 0.5) * base for i in range(nx)]
            rows.append([0.0] + (inner if j == 1 else inner[1:-1]) + [SIDE])
    return rows, SIDE / ny


def zip_rows(lower, upper, xs):
    """Triangles between two rows of node numbers (sorted by x), advancing along whichever row's next edge
    midpoint comes first; xs maps a node number to its x."""
    i = k = 0
    out = []
    while i < len(lower) - 1 or k < len(upper) - 1:
        take_lower = k == len(upper) - 1 or (
            i < len(lower) - 1 and xs[lower[i]] + xs[lower[i + 1]] < xs[upper[k]] + xs[upper[k + 1]])
        if take_lower:
            out.append((lower[i], lower[i + 1], upper[k]))
            i += 1
        else:
            out.append((lower[i], upper[k + 1], upper[k]))
            k += 1
    return out


def lattice(size):
    rows_x, height = rows_of_nodes(size)
    coords, rows = [], []
    for j, xs in enumerate(rows_x):
        rows.append([len(coords) + n + 1 for n in range(len(xs))])
        coords += [(x, j * height) for x in xs]
    xs = {n + 1: c[0] for n, c in enumerate(coords)}
    ys = {n + 1: c[1] for n, c in enumerate(coords)}
    elements = []
    for lower, upper in zip(rows[:-1], rows[1:]):
        for a, b, c in zip_rows(lower, upper, xs):
            if (xs[b] - xs[a]) * (ys[c] - ys[a]) - (xs[c] - xs[a]) * (ys[b] - ys[a]) < 0:
                b, c = c, b
            elements.append((2, 4, (a, b, c)))
    lines = [(1, 1, e) for e in zip(rows[0][:-1], rows[0][1:])]
    lines += [(1, 2, (lo[0], hi[0])) for lo, hi in zip(rows[:-1], rows[1:])]
    lines += [(1, 3, (lo[-1], hi[-1])) for lo, hi in zip(rows[:-1], rows[1:])]
    lines += [(1, 3, e) for e in zip(rows[-1][:-1], rows[-1][1:])]
    return coords, lines + elements


def main():
    size_text, out = positional(2, __doc__.split("\n\n")[1])
    size = number(size_text, "SIZE")
    if not 1e-4 <= size <= 0.6:
        fail(f"SIZE {size} outside [1e-4, 0.6]")
    coords, elements = lattice(size)
    groups = [(1, 1, "axis_x"), (1, 2, "axis_y"), (1, 3, "outer"), (2, 4, "gas")]
    try:
        write_msh22(out, groups, coords, elements)
    except OSError as e:
        fail(f"{out}: {e.strerror}")
    print(f"{out}: {len(coords)} nodes, {sum(1 for e in elements if e[0] == 2)} triangles")


if __name__ == "__main__":
    main()
