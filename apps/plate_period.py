#!/usr/bin/env python3
"""The vibrating beryllium plate's period (docs/gpr-model.md 3.9, inputs/be_plate2d.yaml) from a run's dumps: the
vertical velocity at the plate centre (mass average over the cells whose first-dump centroid lies within RADIUS of the
origin) against time, its zero crossings interpolated linearly, the period = 2 x the mean spacing of consecutive
crossings. Prints the crossings and extrema, and the period in seconds on the last line (nan with fewer than 3
crossings), which is what work_precision.py's `script:` measure reads. tests/scripts/plate_period.py checks it.

usage: plate_period.py OUTDIR [RADIUS]
"""
import glob
import os
import re

import numpy as np

import script_args


def centre_velocity(out, radius):
    """Dump times, the centre's mass-averaged v_y and the whole plate's mean v_y, over the run's dumps."""
    import h5py

    times, vc, vmean, pick = [], [], [], None
    for path in sorted(glob.glob(f"{out}/unilag_*.h5")):
        with open(path[:-3] + ".xmf") as f:
            times.append(float(re.search(r'<Time Value="([^"]+)"', f.read()).group(1)))
        with h5py.File(path, "r") as f:
            # cells in global order, so that the same cells are followed whatever the partition
            order = np.argsort(f["global_id"][:, 0]) if "global_id" in f else slice(None)
            xyz, conn = f["coordinates"][...], f["connectivity"][...][order]
            m = (f["density"][:, 0] * f["volume"][:, 0])[order]
            vy = f["velocity"][:, 1][order]
        if pick is None:
            c = xyz[conn].mean(axis=1)
            pick = np.hypot(c[:, 0], c[:, 1]) < radius
            print(f"{np.count_nonzero(pick)} cells within {radius:g} m of the centre")
        vc.append(np.average(vy[pick], weights=m[pick]))
        vmean.append(np.average(vy, weights=m))
    return np.array(times), np.array(vc), np.array(vmean)


def period(out, radius=1.5e-3):
    """(period or nan, zero crossings, centre |v_y| at the extrema between them) of the run in out."""
    times, vc, vmean = centre_velocity(out, radius)
    print(f"{len(times)} dumps, t = {times[0]:.3g} .. {times[-1]:.3g} s; centre v_y(0) = {vc[0]:.4g} m/s, "
          f"|mean v_y| <= {np.max(np.abs(vmean)):.2e} m/s")
    s = np.sign(vc)
    idx = np.nonzero(s[:-1] * s[1:] < 0)[0]
    crossings = times[idx] - vc[idx] * (times[idx + 1] - times[idx]) / (vc[idx + 1] - vc[idx])
    print("zero crossings (us):", " ".join(f"{c * 1e6:.3f}" for c in crossings))
    if len(crossings) < 3:
        return float("nan"), crossings, []
    halves = np.diff(crossings)
    print(f"half periods (us): {' '.join(f'{x * 1e6:.3f}' for x in halves)}")
    extrema = [np.max(np.abs(vc[(times >= a) & (times <= b)])) for a, b in zip(crossings, crossings[1:])]
    print("centre |v_y| extrema (m/s):", " ".join(f"{e:.3f}" for e in extrema))
    return 2.0 * halves.mean(), crossings, extrema


if __name__ == "__main__":
    args = script_args.positional(1, __doc__, 2)
    if not glob.glob(os.path.join(args[0], "unilag_*.h5")):
        script_args.fail(f"{args[0]}: no dumps unilag_*.h5 (the output folder of a be_plate2d run)")
    print(period(args[0], script_args.number(args[1], "RADIUS") if len(args) > 1 else 1.5e-3)[0])
