#!/usr/bin/env python3
"""The isentropic vortex's geometric floor (docs/gpr-model.md 3.1): the L2 errors of the specific volume and the total
energy that a mesh's straight-edged cells have when their nodes move exactly along the vortex's circles.

Each cell keeps its initial mass; its specific volume is its straight-edged volume at time t over that mass, and its
specific internal energy is the isentrope's at that volume; both are compared with the exact stationary fields at the
cell's centroid, as summary.json's l2_error does. A scheme's own errors come on top of this, unless its node velocities
correct it: on the equilateral lattice of gmsh's frontal mesh nothing can (the doc), elsewhere the acoustic response
can take the error below it.

usage: vortex_floor.py INITIAL_DUMP.h5 T     (the run's first output file, at t = 0; T the time to compare at)
"""
import sys

import numpy as np

# inputs/vortex2d.yaml and vortex3d.yaml: centre (5, 5), epsilon = 5, gamma = 1.4, p = rho^gamma.
GAMMA = 1.4
CENTRE = 5.0


def density(r2):
    return (1.0 - 0.0904655 * np.exp(1.0 - r2)) ** 2.5


def angular_velocity(r2):
    return 0.7957747 * np.exp(0.5 * (1.0 - r2))


def internal_energy(rho):
    return rho ** (GAMMA - 1.0) / (GAMMA - 1.0)


def simplex_volumes(p):
    """Volumes of triangles (p: cells x 3 x 2) or tetrahedra (cells x 4 x 3)."""
    if p.shape[2] == 2:
        return 0.5 * np.abs(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]))
    return np.abs(np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])) / 6.0


def floor(dump, t):
    """(L2 specific volume, L2 total energy) of the cells of dump (an HDF5 output at t = 0) moved exactly to t."""
    import h5py

    with h5py.File(dump, "r") as f:
        cells = f["connectivity"][:]
        dim = cells.shape[1] - 1
        x = f["coordinates"][:, :dim].copy()
        mass = f["density"][:, 0] * f["volume"][:, 0]
    y = x[:, :2] - CENTRE
    angle = angular_velocity((y ** 2).sum(1)) * t
    x[:, 0] = CENTRE + np.cos(angle) * y[:, 0] - np.sin(angle) * y[:, 1]
    x[:, 1] = CENTRE + np.sin(angle) * y[:, 0] + np.cos(angle) * y[:, 1]
    p = x[cells]
    volume = simplex_volumes(p)
    centroid = p.mean(1)
    r2 = ((centroid[:, :2] - CENTRE) ** 2).sum(1)
    exact = density(r2)
    omega_error = volume / mass - 1.0 / exact
    energy_error = internal_energy(mass / volume) - internal_energy(exact) # same velocity: the kinetic parts cancel
    return np.sqrt((volume * omega_error ** 2).sum()), np.sqrt((volume * energy_error ** 2).sum())


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    w, e = floor(sys.argv[1], float(sys.argv[2]))
    print(f"geometric floor at t = {sys.argv[2]}: L2 specific volume {w:.4e}, L2 energy {e:.4e}")
